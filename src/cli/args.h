// Parsing and checking of the command line. Errors name the flag.
//
// Exit codes (main.cpp): 2 for a usage error, a command line that cannot be right (an
// unknown or missing flag, a value that is not a number, out of range, or that the scene
// contradicts, such as a frame past its animation); 1 for work that failed (a scene or
// image that cannot be read or is invalid, an output that cannot be written, an internal
// error); 0 for success.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "base/error.h"
#include "scene/scene.h"

namespace sg {

// A mistake in the command line: exit code 2.
class UsageError : public Error {
 public:
  using Error::Error;
};

// Runs `check` (the validation of flags and their values) and turns the sg::Error it may
// throw into a UsageError.
template <class F>
void check_usage(F&& check) {
  try {
    std::forward<F>(check)();
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

// Validators of number flags; CLI11 prefixes their message with the flag ("--width: must
// be an integer in [1, 16384] (got 'abc')"). Unlike CLI::Range they reject NaN.
CLI::Validator finite_number();
CLI::Validator number_in(double lo, double hi);
CLI::Validator integer_in(long long lo, long long hi);

// The one of `names` that `word` is a slip of ("--widht" of "--width": at most 2 edits,
// a transposition counting one, and fewer than a third of the longer word), else "".
std::string closest_name(const std::string& word, const std::vector<std::string>& names);

// The long and short flags of `app` and of its parents ("--width", "-m").
std::vector<std::string> flag_names(const CLI::App* app);

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
