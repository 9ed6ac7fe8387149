// Announcements of the GL engine's program preparation. A kernel program is compiled and
// linked when an engine is made (staa's at its first frame, and again where a frame's smooth
// terms differ: gl_engine/gl_engine.h), and drivers such as Mesa's llvmpipe compile its machine
// code only at its first dispatch (up to a minute per program there); drivers keep what
// they compiled in an on-disk shader cache (Mesa: ~/.cache/mesa_shader_cache; NVIDIA:
// ~/.nv/GLCache), so a later process prepares the same program in a fraction of a second.
// A user who waits that minute should know why: a preparation that lasts longer than
// kAnnounceAfter (by default) is announced while it runs, and its time when it ends, through
// the notice the program sets (the CLI prints it on stderr); without a notice nothing is
// said.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace sg::gl_engine {

// Receives one line of text (without "sunglint: " or a newline).
using ProgramNotice = std::function<void(const std::string& line)>;
inline constexpr std::chrono::milliseconds kAnnounceAfter{1000};
// `after`: how long a preparation runs before it is announced (the CLI takes it from
// SUNGLINT_GL_NOTICE_AFTER, in seconds; its tests set 0 to see every preparation's time).
void set_program_notice(ProgramNotice notice, std::chrono::milliseconds after = kAnnounceAfter);

// Watches one program's preparation (its compile and link, then its first dispatch): a
// thread waits the notice's `after` for `finish`, and when it has not come says "preparing
// the GL program of NAME ..."; `finish` then says how long the whole preparation took.
class ProgramWatch {
 public:
  explicit ProgramWatch(std::string program);
  ~ProgramWatch();
  ProgramWatch(const ProgramWatch&) = delete;
  ProgramWatch& operator=(const ProgramWatch&) = delete;

  // Starts (or resumes) timing a step; `finish` ends the whole watch. pause() stops the
  // clock between steps (the engine's work between the link and the first dispatch is not
  // preparation).
  void resume();
  void pause();
  void finish();
  double seconds() const;  // preparation so far
  bool announced() const;

 private:
  void watch();

  std::string program_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
  bool running_ = false, finished_ = false, announced_ = false;
  std::chrono::steady_clock::time_point started_{};
  double seconds_ = 0;  // of the steps before the current one
};

}  // namespace sg::gl_engine
