// Progress of long work on stderr, with the time spent and an estimate of the time left.
// On a terminal, one line redrawn in place (a bar). In a log (stderr not a terminal), one
// line per step of the work (a frame of `render`, a method of `compare`), and within a step
// a line only every 30 s, so that short runs log one line per frame and long ones still
// show that they progress and when they will end. Disabled (-q): nothing.
#pragma once

#include <chrono>
#include <string>

namespace sg {

class ProgressBar {
 public:
  // `tty`: draw the bar (default: when stderr is a terminal).
  ProgressBar(std::string label, bool enabled);
  ProgressBar(std::string label, bool enabled, bool tty);
  ~ProgressBar();
  // `done` of `total` units of the whole work.
  void update(long done, long total);
  // A step of the work ended (`what`, e.g. "frame 3"), with `done` of `total` units done.
  void step(const std::string& what, long done, long total);
  void set_label(std::string label) { label_ = std::move(label); }
  // The time left, when the caller knows better than the share done (compare: from a
  // pilot's costs and the measured time, report/plan.h); < 0: extrapolate the share.
  void set_seconds_left(double s) { seconds_left_ = s; }
  void finish();

 private:
  double seconds() const;
  double eta(double fraction, double secs) const;
  void log_line(const std::string& what, double fraction);

  std::string label_;
  bool enabled_, tty_, finished_ = false;
  int last_permille_ = -1;
  double last_line_ = 0;
  double seconds_left_ = -1;  // seconds, when the last log line was printed
  std::chrono::steady_clock::time_point start_;
};

// "12.3 s", "4 min 05 s", "2 h 03 min": a duration as the progress lines print it.
std::string format_duration(double seconds);

}  // namespace sg
