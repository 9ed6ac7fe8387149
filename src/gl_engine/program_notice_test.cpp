// The GL program's preparation is announced when it lasts (program_notice.h): a step
// longer than the notice's delay gets a line while it runs and one with its time at the
// end; a short one says nothing; the time between paused steps does not count. No GL
// context is needed: the steps are sleeps.
#include "gl_engine/program_notice.h"

#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace sg::gl_engine {
namespace {

using namespace std::chrono_literals;

struct Lines {
  std::mutex m;
  std::vector<std::string> lines;
  void listen(std::chrono::milliseconds after) {
    set_program_notice(
        [this](const std::string& l) {
          std::lock_guard<std::mutex> lock(m);
          lines.push_back(l);
        },
        after);
  }
  ~Lines() { set_program_notice({}); }
};

TEST(ProgramWatch, ALongPreparationIsAnnouncedWithItsTime) {
  Lines out;
  out.listen(100ms);
  ProgramWatch w("staa");
  w.resume();
  std::this_thread::sleep_for(250ms);
  EXPECT_TRUE(w.announced());  // while it runs
  w.finish();
  ASSERT_EQ(out.lines.size(), 2u);
  EXPECT_EQ(out.lines[0].rfind("preparing the GL program of staa (", 0), 0u) << out.lines[0];
  EXPECT_EQ(out.lines[1].rfind("the GL program of staa took 0.", 0), 0u) << out.lines[1];
  EXPECT_NE(out.lines[1].find(" s to prepare"), std::string::npos) << out.lines[1];
}

TEST(ProgramWatch, AShortOneSaysNothing) {
  Lines out;
  out.listen(1000ms);
  ProgramWatch w("point");
  w.resume();
  std::this_thread::sleep_for(20ms);
  w.finish();
  EXPECT_TRUE(out.lines.empty());
  EXPECT_LT(w.seconds(), 0.5);
}

TEST(ProgramWatch, PausedTimeDoesNotCount) {
  Lines out;
  out.listen(200ms);
  ProgramWatch w("reference");
  w.resume();
  std::this_thread::sleep_for(120ms);
  w.pause();
  std::this_thread::sleep_for(600ms);  // the engine's own work between the steps
  EXPECT_FALSE(w.announced());
  w.resume();
  std::this_thread::sleep_for(200ms);  // 320 ms of preparation in all
  w.finish();
  ASSERT_EQ(out.lines.size(), 2u);
  EXPECT_GE(w.seconds(), 0.3);
  EXPECT_LT(w.seconds(), 0.8);  // not the paused 600 ms on top (0.48 s of slack for load)
}

TEST(ProgramWatch, NobodyListeningIsSilent) {
  set_program_notice({});
  ProgramWatch w("point");
  w.resume();
  std::this_thread::sleep_for(10ms);
  w.finish();
  EXPECT_FALSE(w.announced());
}

}  // namespace
}  // namespace sg::gl_engine
