// Where the tests and benchmarks find the checkout and the build folder. The folders are
// compiled into one small library (testing/paths.cpp) and not into every test's flags, so
// that a clone elsewhere reuses the compiler cache for every other object (docs/ci.md).
#pragma once

#include <string>

namespace sg::testing {

// The checkout the tests read scenes and fixtures from: $SUNGLINT_SOURCE_DIR where set (a
// test program carried to another machine, scripts/gpu-check.sh), else the one it was
// built from.
std::string source_dir();

// The build folder the tests write their outputs under (test_out/, test-cache/).
std::string binary_dir();

}  // namespace sg::testing
