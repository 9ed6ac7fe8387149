// The study as tasks (report/plan.h): every unit of a study is planned exactly once, a unit
// in the cache is never planned again, tasks group units in order, the plan survives its
// JSON, a study rendered task by task and merged equals the local run frame for frame and
// figure for figure, and the time left follows a hand-made cost table.
#include "report/plan.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "base/error.h"
#include "methods/point.h"
#include "report/cache.h"
#include "report/study.h"
#include "testing/testing.h"

namespace sg {
namespace {
namespace fs = std::filesystem;

// A stateful method: point sampling averaged with its previous frame (as TAA's history).
class Ema final : public Method {
 public:
  std::string name() const override { return "ema"; }
  bool stateful() const override { return true; }
  void begin_frame(const FrameContext& ctx) override { point_.begin_frame(ctx); }
  RadianceWeights weights(const FrameContext& ctx, int i, int j) const override {
    return point_.weights(ctx, i, j);
  }
  void end_frame(const FrameContext&, Image& img) override {
    if (!prev_.data.empty()) {
      for (size_t k = 0; k < img.size(); ++k)
        img.data[k] = 0.5f * img.data[k] + 0.5f * prev_.data[k];
    }
    prev_ = img;
  }
  void reset() override { prev_ = Image(); }

 private:
  PointMethod point_;
  Image prev_;
};

StudyVariant variant(const std::string& label, const std::string& name, SampleCounts samples = {}) {
  StudyVariant v;
  v.label = label;
  v.name = name;
  v.options.samples = samples;
  v.options.samples_given = true;
  return v;
}

StudyConfig tiny_study(const std::string& dir) {
  StudyConfig c;
  Scene s = testing::small_scene(
      {Wave{0.12, {0.1, -0.9}, 2.9, 0.3}, Wave{0.04, {-0.5, -2.2}, 4.6, 1.2}}, 20, 12);
  s.name = "tiny";
  c.scenes.push_back({"tiny.json", s});
  s.name = "tiny2";
  s.light.angular_radius_deg = 2;
  c.scenes.push_back({"tiny2.json", s});
  c.reference = variant("reference --samples 2x2x1", "reference", {2, 2, 1});
  c.methods = {variant("point", "point"),
               variant("supersample --samples 2x2x1", "supersample", {2, 2, 1})};
  StudyVariant ema = variant("ema", "ema");
  ema.make = [] { return std::make_unique<Ema>(); };
  c.methods.push_back(ema);
  c.budgets = {variant("supersample --samples 1x1x1", "supersample", {1, 1, 1}),
               variant("supersample --samples 2x2x1", "supersample", {2, 2, 1})};
  c.equal_cost_target = "point";
  c.first_frame = 1;
  c.last_frame = 3;
  c.out_dir = dir;
  c.threads = 1;
  c.video = false;
  return c;
}

std::string test_dir() {
  const std::string d = (fs::path(sg::testing::binary_dir()) / "test_out/plan" /
                         ::testing::UnitTest::GetInstance()->current_test_info()->name())
                            .string();
  fs::remove_all(d);
  return d;
}

std::string bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Plan, EveryUnitOnceAndACachedUnitNeverPlannedAgain) {
  const StudyConfig c = tiny_study(test_dir());
  const std::vector<StudyUnit> all = study_units(c, false);
  // Per scene: 2 batches x 3 frames of the reference, point and supersample 2x2x1 frame by
  // frame, ema's range whole, the budget 1x1x1 (2x2x1 is a method already).
  EXPECT_EQ(all.size(), 2u * (6 + 3 + 3 + 1 + 3));
  std::set<std::string> files;
  for (const auto& u : all)
    files.insert(u.file);
  EXPECT_EQ(files.size(), all.size()) << "a unit planned twice";
  int stateful = 0, batches = 0;
  for (const auto& u : all) {
    stateful += u.last > u.first;
    batches += u.batch >= 0;
  }
  EXPECT_EQ(stateful, 2);
  EXPECT_EQ(batches, 12);
  EXPECT_EQ(study_units(c, true).size(), all.size());

  // Render every third unit: exactly those leave the plan; rendering them again is nothing.
  std::vector<StudyUnit> some;
  for (size_t k = 0; k < all.size(); k += 3)
    some.push_back(all[k]);
  EXPECT_EQ(render_units(c, some), int(some.size()));
  EXPECT_EQ(render_units(c, some), 0);
  const std::vector<StudyUnit> left = study_units(c, true);
  EXPECT_EQ(left.size(), all.size() - some.size());
  std::set<std::string> planned;
  for (const auto& u : left)
    planned.insert(u.file);
  for (const auto& u : some)
    EXPECT_FALSE(planned.count(u.file)) << u.id << " planned again";
  for (const auto& u : all) {
    bool in_some = false;
    for (const auto& s : some)
      in_some = in_some || s.file == u.file;
    EXPECT_EQ(planned.count(u.file), in_some ? 0u : 1u) << u.id;
  }

  // Tasks: every planned unit in exactly one task, in order, grouped by cost.
  std::vector<PlannedUnit> units;
  for (const auto& u : left)
    units.push_back({u.id, u.file, 1.0});
  for (double seconds : {0.0, 1.0, 2.5, 1e9}) {
    const std::vector<PlanTask> tasks = group_into_tasks(units, seconds);
    std::vector<std::string> order;
    for (const auto& t : tasks) {
      EXPECT_FALSE(t.units.empty());
      for (const auto& u : t.units)
        order.push_back(u.file);
    }
    ASSERT_EQ(order.size(), units.size()) << seconds;
    for (size_t k = 0; k < units.size(); ++k)
      EXPECT_EQ(order[k], units[k].file);
    const size_t want = seconds == 0     ? units.size()
                        : seconds >= 1e9 ? 1
                                         : (units.size() + size_t(std::ceil(seconds)) - 1) /
                                               size_t(std::ceil(seconds));
    EXPECT_EQ(tasks.size(), want) << seconds;
  }
  // A merge of an incomplete cache names what is missing and renders nothing.
  try {
    merge_study(c);
    ADD_FAILURE() << "merged an incomplete cache";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(left.size()) + " of the study's units"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(study_units(c, true).size(), left.size());
}

TEST(Plan, ShardedEqualsLocalFrameForFrame) {
  const std::string dir = test_dir();
  StudyConfig local = tiny_study(dir + "/local");
  const StudyResults a = run_study(local);
  StudyConfig sharded = tiny_study(dir + "/sharded");
  // Tasks of two units each, run in reverse order (as a job array may), then the merge.
  std::vector<StudyUnit> units = study_units(sharded, true);
  std::vector<PlannedUnit> planned;
  for (const auto& u : units)
    planned.push_back({u.id, u.file, 1});
  const std::vector<PlanTask> tasks = group_into_tasks(planned, 2);
  for (size_t t = tasks.size(); t-- > 0;) {
    std::vector<StudyUnit> mine;
    for (const auto& p : tasks[t].units) {
      for (const auto& u : units) {
        if (u.file == p.file) mine.push_back(u);
      }
    }
    EXPECT_EQ(render_units(sharded, mine), int(mine.size()));
  }
  const StudyResults b = merge_study(sharded);
  // The same frames, byte for byte.
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir + "/local/cache")) {
    const fs::path other = fs::path(dir + "/sharded/cache") / e.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_EQ(bytes(e.path()).size() > 0, true);
    if (e.path().extension() == ".exr") {
      EXPECT_EQ(bytes(e.path()), bytes(other)) << e.path();
      ++files;
    }
  }
  EXPECT_EQ(files, int(units.size()) + 2 * 2);  // ema's range: 3 frames in one unit
  // The same figures.
  ASSERT_EQ(a.scenes.size(), b.scenes.size());
  for (size_t s = 0; s < a.scenes.size(); ++s) {
    for (size_t m = 0; m < a.scenes[s].methods.size(); ++m) {
      const VariantResult &x = a.scenes[s].methods[m], &y = b.scenes[s].methods[m];
      EXPECT_EQ(x.frames_rendered, 3);
      EXPECT_EQ(y.frames_rendered, 0);
      EXPECT_EQ(y.frames_cached, 3);
      for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(x.regions[k].rmse, y.regions[k].rmse) << x.label;
        EXPECT_EQ(x.regions[k].temporal_error, y.regions[k].temporal_error) << x.label;
        EXPECT_EQ(x.regions[k].reference_se, y.regions[k].reference_se) << x.label;
      }
    }
    EXPECT_GT(a.scenes[s].reference.at(Region::image).reference_se, 0);
  }
}

TEST(Plan, JsonRoundTripAndRefusals) {
  StudyPlan p;
  p.command = "sunglint compare x.json -m point --out o";
  p.study = study_fingerprint({"a.exr", "b.exr", "c.exr"});
  p.units_total = 3;
  p.units_cached = 1;
  p.pilot_seconds = 0.25;
  p.tasks =
      group_into_tasks({{"x: point, frame 0", "a.exr", 0.5}, {"x: point, frame 1", "b.exr", 2}}, 0);
  const StudyPlan q = plan_from_json(plan_to_json(p), "plan.json");
  EXPECT_EQ(plan_to_json(q), plan_to_json(p));
  EXPECT_EQ(q.tasks.size(), 2u);
  EXPECT_DOUBLE_EQ(q.core_seconds(), 2.5);
  EXPECT_DOUBLE_EQ(q.longest_task(), 2);
  EXPECT_NE(study_fingerprint({"a.exr", "b.exr"}), p.study);
  EXPECT_NE(plan_table(p).find("3 units, 1 in the cache; 2 to render in 2 tasks"),
            std::string::npos)
      << plan_table(p);
  EXPECT_THROW(plan_from_json("{\"schema\": \"other\"}", "x.json"), Error);
  EXPECT_THROW(plan_from_json("not json", "x.json"), Error);
}

// The time left against a hand-made cost table: units estimated at 1, 3 and 6 core-seconds
// and a report of 2 s, on 2 threads (a prior of 0.5 wall seconds per core-second).
TEST(TimeEstimate, FollowsAHandMadeCostTable) {
  TimeEstimate e(10, 0.5, 2);
  // Nothing measured: the prior.
  EXPECT_DOUBLE_EQ(e.rate(), 0.5);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 10 * 0.5 + 2);
  EXPECT_DOUBLE_EQ(e.fraction(), 0);
  // The first unit (1 core-s) took 2 s: the prior weighs 2 % of the total (0.2 core-s),
  // so the rate moves to (0.2 * 0.5 + 2) / (0.2 + 1) = 1.75.
  e.done(1, 2);
  EXPECT_DOUBLE_EQ(e.rate(), 1.75);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 9 * 1.75 + 2);
  // Half of the second unit: its half no longer counts as left.
  e.partial(1.5);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 7.5 * 1.75 + 2);
  // The second took 3 s: (0.1 + 5) / (0.2 + 4).
  e.done(3, 3);
  EXPECT_DOUBLE_EQ(e.rate(), 5.1 / 4.2);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 6 * 5.1 / 4.2 + 2);
  e.done(6, 6);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 2);
  e.fixed_done(2);
  EXPECT_DOUBLE_EQ(e.seconds_left(), 0);
  EXPECT_DOUBLE_EQ(e.fraction(), 1);
  // An estimate 4 times too low everywhere: after a tenth of the work, the time left is
  // within 15 % of the truth, and within a factor of 2 after 2 %.
  TimeEstimate low(100, 1.0);
  low.done(2, 8);
  EXPECT_GT(low.seconds_left(), 0.5 * 98 * 4);
  for (int k = 2; k < 10; ++k)
    low.done(1, 4);
  const double truth = 90 * 4;
  EXPECT_GT(low.seconds_left(), 0.85 * truth);
  EXPECT_LT(low.seconds_left(), 1.15 * truth);
}

}  // namespace
}  // namespace sg
