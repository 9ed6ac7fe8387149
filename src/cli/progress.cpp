#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

namespace sg {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled),
      tty_(::isatty(2) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(long done, long total) {
  if (!enabled_ || total <= 0) return;
  const double f = static_cast<double>(done) / total;
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (tty_) {
    int permille = static_cast<int>(f * 1000);
    if (permille == last_permille_) return;
    last_permille_ = permille;
    const int width = 30, filled = static_cast<int>(f * width);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    double eta = f > 0 ? secs * (1 - f) / f : 0;
    std::fprintf(stderr, "\r%s [%s] %5.1f%%  %6.1fs  eta %6.1fs ", label_.c_str(), bar.c_str(),
                 100 * f, secs, eta);
    std::fflush(stderr);
  } else {
    int decile = static_cast<int>(f * 10);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s %3d%%  %.1fs\n", label_.c_str(), decile * 10, secs);
  }
}

void ProgressBar::finish() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  if (tty_ && last_permille_ >= 0) std::fprintf(stderr, "\n");
}

}  // namespace sg
