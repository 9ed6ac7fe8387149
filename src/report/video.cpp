#include "report/video.h"

#include <algorithm>
#include <cmath>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "base/atomic_file.h"
#include "base/error.h"

extern char** environ;

namespace sg {

double playback_fps(double scene_fps, int frames, double min_seconds) {
  if (frames <= 0 || !(min_seconds > 0)) return scene_fps;
  // Rounded down to 4 decimals, so that the rate ffmpeg is given ("%.6g") never shortens the
  // loop below min_seconds.
  return std::min(scene_fps, std::floor(frames / min_seconds * 1e4) / 1e4);
}
namespace {

// Runs `argv` with `input` on its standard input (its standard output discarded when
// `quiet`); returns its exit status. ENOENT from the spawn becomes a clear message.
int run_with_input(const std::vector<std::string>& argv, const std::vector<uint8_t>& input,
                   bool quiet = false) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw Error("ffmpeg: cannot create a pipe: " + std::string(std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  if (quiet) posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
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

namespace {

void encode(const std::string& path, int width, int height, int channels, double fps,
            const std::vector<std::vector<uint8_t>>& frames, const std::string& ffmpeg) {
  if (frames.empty()) throw Error(path + ": no frames to encode");
  const int w = width + (width & 1), h = height + (height & 1);
  const size_t px = static_cast<size_t>(channels);
  std::vector<uint8_t> raw;
  raw.reserve(size_t(w) * h * px * frames.size());
  for (const auto& f : frames) {
    if (f.size() != size_t(width) * height * px) throw Error(path + ": frame size differs");
    for (int j = 0; j < h; ++j) {
      const int sj = std::min(j, height - 1);  // padding repeats the last row and column
      for (int i = 0; i < w; ++i) {
        const uint8_t* p = &f[(size_t(sj) * width + std::min(i, width - 1)) * px];
        raw.insert(raw.end(), p, p + px);
      }
    }
  }
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", fps);
  write_file_atomic_with(path, [&](const std::string& tmp) {
    std::vector<std::string> argv = {ffmpeg,         "-nostdin",
                                     "-hide_banner", "-loglevel",
                                     "error",        "-y",
                                     "-f",           "rawvideo",
                                     "-pix_fmt",     channels == 3 ? "rgb24" : "gray",
                                     "-s",           std::to_string(w) + "x" + std::to_string(h),
                                     "-framerate",   rate,
                                     "-i",           "pipe:0"};
    if (channels == 3) {
      for (const char* a : {"-vf", "scale=out_color_matrix=bt709:out_range=tv", "-colorspace",
                            "bt709", "-color_primaries", "bt709", "-color_trc", "bt709"})
        argv.push_back(a);
    }
    for (const char* a :
         {"-c:v",       "libx264",  "-preset",   "medium",        "-crf",      "18",
          "-threads",   "1",        "-pix_fmt",  "yuv420p",       "-bitexact", "-fflags",
          "+bitexact",  "-flags:v", "+bitexact", "-map_metadata", "-1",        "-movflags",
          "+faststart", "-f",       "mp4"})
      argv.push_back(a);
    argv.push_back(tmp);
    const int status = run_with_input(argv, raw);
    if (status != 0) {
      throw Error(ffmpeg + " failed (exit status " + std::to_string(status) + ")");
    }
  });
}

}  // namespace

void check_ffmpeg(const std::string& ffmpeg) {
  const int status = run_with_input(
      {ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-version"}, {}, true);
  if (status != 0)
    throw Error(ffmpeg + " -version failed (exit status " + std::to_string(status) + ")");
}

void encode_h264(const std::string& path, int width, int height, double fps,
                 const std::vector<std::vector<uint8_t>>& frames, const std::string& ffmpeg) {
  encode(path, width, height, 1, fps, frames, ffmpeg);
}

void encode_h264_rgb(const std::string& path, int width, int height, double fps,
                     const std::vector<std::vector<uint8_t>>& frames, const std::string& ffmpeg) {
  encode(path, width, height, 3, fps, frames, ffmpeg);
}

}  // namespace sg
