// The checkout's and the build's folders, as CMake knew them (testing/paths.h).
#include "testing/paths.h"

#include <cstdlib>

namespace sg::testing {

std::string source_dir() {
  const char* d = std::getenv("SUNGLINT_SOURCE_DIR");
  return d && *d ? std::string(d) : std::string(SG_SOURCE_DIR);
}

std::string binary_dir() {
  return SG_BINARY_DIR;
}

}  // namespace sg::testing
