// Parsing of the CLI's composite arguments. Errors name the flag.
#pragma once

#include <string>

#include "scene/scene.h"

namespace sg {

struct FrameRange {
  int first = 0, last = 0;
  int count() const { return last - first + 1; }
};

// "A-B" or "A"; checked against the scene's animation when `scene` is given.
FrameRange parse_frame_range(const std::string& text, const std::string& flag);
void check_frame(int frame, const Scene& scene, const std::string& flag);

// --width/--height overrides (0: not given); a missing one follows the scene's aspect
// ratio. Checked by the scene's rules ("--width: must be >= 1").
void apply_image_size(Scene& scene, int width, int height);

}  // namespace sg
