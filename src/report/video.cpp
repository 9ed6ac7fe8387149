#include "report/video.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"

extern char** environ;

namespace sg {
namespace {

// Runs `argv` with `input` on its standard input; returns its exit status. ENOENT from
// the spawn becomes a clear message.
int run_with_input(const std::vector<std::string>& argv, const std::vector<uint8_t>& input) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw Error("ffmpeg: cannot create a pipe: " + std::string(std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  std::vector<char*> args;
  for (const auto& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (rc != 0) {
    ::close(fds[1]);
    if (rc == ENOENT) {
      throw Error(argv[0] +
                  ": not found; install it (Debian package 'ffmpeg', scripts/install-deps.sh) "
                  "or pass --no-video");
    }
    throw Error(argv[0] + ": cannot start: " + std::strerror(rc));
  }
  // A writer to a process that died gets SIGPIPE; ignore it while writing (EPIPE instead).
  struct sigaction ignore {
  }, old{};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, &old);
  size_t off = 0;
  while (off < input.size()) {
    const ssize_t n = ::write(fds[1], input.data() + off, input.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the process stopped reading; its exit status tells why
    off += static_cast<size_t>(n);
  }
  ::close(fds[1]);
  ::sigaction(SIGPIPE, &old, nullptr);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status)
                           : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

void encode_h264(const std::string& path, int width, int height, double fps,
                 const std::vector<std::vector<uint8_t>>& frames, const std::string& ffmpeg) {
  if (frames.empty()) throw Error(path + ": no frames to encode");
  const int w = width + (width & 1), h = height + (height & 1);
  std::vector<uint8_t> raw;
  raw.reserve(size_t(w) * h * frames.size());
  for (const auto& f : frames) {
    if (f.size() != size_t(width) * height) throw Error(path + ": frame size differs");
    for (int j = 0; j < h; ++j) {
      const int sj = std::min(j, height - 1);  // padding repeats the last row and column
      for (int i = 0; i < w; ++i)
        raw.push_back(f[size_t(sj) * width + std::min(i, width - 1)]);
    }
  }
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  write_file_atomic_with(path, [&](const std::string& tmp) {
    const std::vector<std::string> argv = {
        ffmpeg,       "-nostdin",  "-hide_banner", "-loglevel",
        "error",      "-y",        "-f",           "rawvideo",
        "-pix_fmt",   "gray",      "-s",           std::to_string(w) + "x" + std::to_string(h),
        "-framerate", rate,        "-i",           "pipe:0",
        "-c:v",       "libx264",   "-preset",      "medium",
        "-crf",       "18",        "-threads",     "1",
        "-pix_fmt",   "yuv420p",   "-bitexact",    "-fflags",
        "+bitexact",  "-flags:v",  "+bitexact",    "-map_metadata",
        "-1",         "-movflags", "+faststart",   "-f",
        "mp4",        tmp};
    const int status = run_with_input(argv, raw);
    if (status != 0) {
      throw Error(ffmpeg + " failed (exit status " + std::to_string(status) + ")");
    }
  });
}

}  // namespace sg
