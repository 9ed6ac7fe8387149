// The one exception type of sunglint. Every message a user can see names its culprit
// first: a scene key path ("surface.waves[3].amplitude: must be >= 0"), a flag
// ("--samples: expected SxSxT"), or a file ("out/x.exr: cannot write: ...").
// The CLI prints it and exits non-zero; nothing catches it in between.
#pragma once

#include <stdexcept>
#include <string>

namespace sg {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace sg
