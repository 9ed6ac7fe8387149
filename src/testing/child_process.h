// Runs the current test again in a fresh process: the same test binary (/proc/self/exe)
// with --gtest_filter naming this test and SG_TEST_CHILD=1 in its environment, for checks
// that need a process in which nothing has happened yet (Mesa reads
// MESA_GL_VERSION_OVERRIDE once per process). The test's body starts with
//   if (sg::testing::in_child()) { ...; std::exit(code); }
// and the parent calls run_child() for the child's exit code and stderr. Unlike gtest's
// "threadsafe" death tests this works when the binary was started through PATH.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

extern char** environ;

namespace sg::testing {

inline bool in_child() {
  const char* v = std::getenv("SG_TEST_CHILD");
  return v && std::string(v) == "1";
}

struct ChildResult {
  int exit_code = -1;  // -1: killed by a signal or not started
  std::string output;  // stdout and stderr
};

inline ChildResult run_child() {
  const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string filter =
      std::string("--gtest_filter=") + t->test_suite_name() + "." + t->name();
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("SG_TEST_CHILD=", 0) != 0) env.push_back(*e);
  env.push_back("SG_TEST_CHILD=1");
  // A window test's child uses the parent's X server (testing/xvfb.h).
  if (const char* d = std::getenv("DISPLAY"); d && *d && !std::getenv("SUNGLINT_TEST_DISPLAY"))
    env.push_back(std::string("SUNGLINT_TEST_DISPLAY=") + d);
  std::vector<char*> envp;
  for (std::string& s : env)
    envp.push_back(s.data());
  envp.push_back(nullptr);
  std::string exe = "/proc/self/exe";
  std::vector<char*> argv = {exe.data(), const_cast<char*>(filter.c_str()), nullptr};

  ChildResult r;
  int fds[2];
  if (pipe(fds) != 0) return r;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  pid_t pid = -1;
  const int err = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (err != 0) {
    close(fds[0]);
    r.output = "posix_spawn failed";
    return r;
  }
  char buf[4096];
  ssize_t n;
  while ((n = read(fds[0], buf, sizeof buf)) > 0)
    r.output.append(buf, size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  return r;
}

}  // namespace sg::testing
