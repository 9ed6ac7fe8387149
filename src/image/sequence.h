// Image sequences on disk: a printf-style pattern with one integer conversion names the
// frames, e.g. "out/frame_%04d.exr" -> out/frame_0007.exr for frame 7. Only %d, %Nd and
// %0Nd are accepted (and %% for a literal percent sign), so a pattern can never read
// arbitrary arguments.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace sg {

// True when `text` holds a frame conversion (%d, %Nd, %0Nd).
bool is_frame_pattern(const std::string& text);

// The file name of `frame`; throws sg::Error naming `flag` on a malformed pattern.
std::string format_frame_path(const std::string& pattern, int frame,
                              const std::string& flag = "pattern");

// Reads frames first..last of a pattern.
std::vector<Image> read_sequence(const std::string& pattern, int first, int last);

}  // namespace sg
