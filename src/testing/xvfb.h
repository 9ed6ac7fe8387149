// An X server for the tests of windows: starts `Xvfb -displayfd` (it picks a free display
// number, so tests running at once get their own), sets DISPLAY, and stops it when
// destroyed. With SUNGLINT_TEST_DISPLAY set, the tests use that display instead
// (scripts/gpu-run.sh --x starts one Xvfb, with the Mesa pieces its GLX needs). Where Xvfb is
// missing or does not start, `reason` says why and the tests skip (fail under
// SUNGLINT_REQUIRE_GL=1, as in CI). Shell tests use `xvfb-run -a` instead.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace sg::testing {

class Xvfb {
 public:
  explicit Xvfb(const std::string& screen = "1280x1024x24") {
    if (const char* given = std::getenv("SUNGLINT_TEST_DISPLAY"); given && *given) {
      display_ = given;
      setenv("DISPLAY", given, 1);
      return;
    }
    int fds[2];
    if (pipe(fds) != 0) {
      reason_ = "pipe failed";
      return;
    }
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten",
             "tcp", "-noreset", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    // Xvfb writes its display number and a newline once it accepts clients.
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    while (poll(&p, 1, 20000) > 0) {
      char c;
      if (read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    close(fds[0]);
    if (number.empty()) {
      int status = 0;
      kill(pid_, SIGTERM);
      waitpid(pid_, &status, 0);
      pid_ = -1;
      reason_ = WIFEXITED(status) && WEXITSTATUS(status) == 127
                    ? "Xvfb is not installed (Debian package xvfb)"
                    : "Xvfb did not start";
      return;
    }
    display_ = ":" + number;
    setenv("DISPLAY", display_.c_str(), 1);
  }
  ~Xvfb() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;

  bool running() const { return !display_.empty(); }
  const std::string& display() const { return display_; }
  const std::string& reason() const { return reason_; }

 private:
  pid_t pid_ = -1;
  std::string display_, reason_;
};

}  // namespace sg::testing
