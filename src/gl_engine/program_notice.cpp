#include "gl_engine/program_notice.h"

#include <cstdio>
#include <utility>

namespace sg::gl_engine {
namespace {

std::mutex notice_mutex;
ProgramNotice& notice_slot() {
  static ProgramNotice n;
  return n;
}
std::chrono::milliseconds notice_after = kAnnounceAfter;

ProgramNotice current_notice() {
  std::lock_guard<std::mutex> lock(notice_mutex);
  return notice_slot();
}

std::chrono::milliseconds current_after() {
  std::lock_guard<std::mutex> lock(notice_mutex);
  return notice_after;
}

}  // namespace

void set_program_notice(ProgramNotice notice, std::chrono::milliseconds after) {
  std::lock_guard<std::mutex> lock(notice_mutex);
  notice_slot() = std::move(notice);
  notice_after = after;
}

ProgramWatch::ProgramWatch(std::string program) : program_(std::move(program)) {}

ProgramWatch::~ProgramWatch() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ProgramWatch::resume() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_ || running_) return;
  running_ = true;
  started_ = std::chrono::steady_clock::now();
  // The watching thread starts with the first step, when someone listens.
  if (!thread_.joinable() && current_notice()) thread_ = std::thread([this] { watch(); });
  wake_.notify_all();
}

void ProgramWatch::pause() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!running_) return;
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  running_ = false;
}

void ProgramWatch::finish() {
  pause();
  bool said = false;
  double s = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    finished_ = true;
    said = announced_;
    s = seconds_;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  if (!said) return;
  if (ProgramNotice n = current_notice()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f s", s);
    n("the GL program of " + program_ + " took " + buf + " to prepare");
  }
}

double ProgramWatch::seconds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return seconds_ +
         (running_
              ? std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()
              : 0);
}

bool ProgramWatch::announced() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return announced_;
}

// Waits until the steps so far have run kAnnounceAfter, then says so once.
void ProgramWatch::watch() {
  const std::chrono::milliseconds after = current_after();
  std::unique_lock<std::mutex> lock(mutex_);
  while (!finished_) {
    if (!running_) {
      wake_.wait(lock);
      continue;
    }
    const auto spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_);
    const auto left = after - std::chrono::duration_cast<std::chrono::milliseconds>(
                                  spent + std::chrono::duration<double>(seconds_));
    if (left.count() > 0 && after.count() > 0) {
      wake_.wait_for(lock, left);
      continue;
    }
    announced_ = true;
    lock.unlock();
    if (ProgramNotice n = current_notice()) {
      n("preparing the GL program of " + program_ +
        " (its first compile on a driver takes minutes on a software renderer such as "
        "llvmpipe; later runs read it from the driver's shader cache)...");
    }
    return;
  }
}

}  // namespace sg::gl_engine
