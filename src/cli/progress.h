// A progress bar on stderr for long work. On a terminal it redraws one line; in a log
// (stderr not a terminal) it prints a line at every 10% so logs stay short.
#pragma once

#include <chrono>
#include <string>

namespace sg {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();
  void update(long done, long total);
  void set_label(std::string label) { label_ = std::move(label); }
  void finish();

 private:
  std::string label_;
  bool enabled_, tty_, finished_ = false;
  int last_decile_ = -1;
  int last_permille_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sg
