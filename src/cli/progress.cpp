#include "cli/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace sg {
namespace {

// In a log, a line within a step at most this often.
constexpr double kLogInterval = 30;  // seconds

}  // namespace

std::string format_duration(double s) {
  char buf[64];
  if (!(s >= 0) || !std::isfinite(s)) return "?";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else if (s < 3600) {
    const long t = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", t / 60, t % 60);
  } else {
    const long t = std::lround(s / 60);
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", t / 60, t % 60);
  }
  return buf;
}

ProgressBar::ProgressBar(std::string label, bool enabled)
    : ProgressBar(std::move(label), enabled, ::isatty(2) != 0) {}

ProgressBar::ProgressBar(std::string label, bool enabled, bool tty)
    : label_(std::move(label)),
      enabled_(enabled),
      tty_(tty),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

double ProgressBar::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double ProgressBar::eta(double f, double secs) const {
  if (seconds_left_ >= 0) return seconds_left_;
  return f > 0 ? secs * (1 - f) / f : -1;
}

void ProgressBar::log_line(const std::string& what, double f) {
  const double secs = seconds();
  last_line_ = secs;
  const double left = eta(f, secs);
  const std::string tail = left >= 0 && f < 1 ? ", about " + format_duration(left) + " left" : "";
  std::fprintf(stderr, "%s%s%s %5.1f%%  %s%s\n", label_.c_str(), what.empty() ? "" : " ",
               what.c_str(), 100 * f, format_duration(secs).c_str(), tail.c_str());
  std::fflush(stderr);
}

void ProgressBar::update(long done, long total) {
  if (!enabled_ || total <= 0) return;
  const double f = static_cast<double>(done) / total;
  if (tty_) {
    int permille = static_cast<int>(f * 1000);
    if (permille == last_permille_) return;
    last_permille_ = permille;
    const int width = 30, filled = static_cast<int>(f * width);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    const double secs = seconds();
    const double left = eta(f, secs);
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %s  eta %s   ", label_.c_str(), bar.c_str(), 100 * f,
                 format_duration(secs).c_str(), format_duration(left).c_str());
    std::fflush(stderr);
  } else if (seconds() - last_line_ >= kLogInterval && done < total) {
    log_line("", f);
  }
}

void ProgressBar::step(const std::string& what, long done, long total) {
  if (!enabled_ || total <= 0) return;
  if (tty_) {
    update(done, total);
  } else {
    log_line(what, static_cast<double>(done) / total);
  }
}

void ProgressBar::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  if (tty_ && last_permille_ >= 0) std::fprintf(stderr, "\n");
}

}  // namespace sg
