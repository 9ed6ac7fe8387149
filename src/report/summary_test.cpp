// The report's summary and Table 1 in words, against a hand-made results file
// (tests/report/summary_results.json: three scenes whose figures were chosen so that each
// case occurs once): the lowest RMSE and temporal error per scene, a best RMSE within the
// reference's noise of the next, the target's RMSE against supersampling at equal cost
// (interpolated on simple, below the curve on high, no curve on sunset), its cost and
// temporal error against point's, the sentence over the study, and where the paper's
// method wins and loses. The expected sentences are worked out by hand from the file.
#include "report/summary.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "report/html.h"
#include "report/paper.h"
#include "report/results.h"
#include "testing/paths.h"

namespace sg {
namespace {

StudyResults hand_made() {
  const std::string path = testing::source_dir() + "/tests/report/summary_results.json";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return results_from_json(text.str(), path);
}

std::string md(const std::string& s) {
  return "`" + s + "`";
}

TEST(Summary, PerSceneFigures) {
  const StudySummary s = summarise(hand_made());
  ASSERT_EQ(s.scenes.size(), 3u);
  EXPECT_EQ(s.target, "staa");
  const SceneSummary& simple = s.scenes[0];
  EXPECT_EQ(simple.best_rmse.label, "staa");
  EXPECT_EQ(simple.next_rmse.label, "lean");
  EXPECT_FALSE(simple.rmse_within_noise);
  EXPECT_EQ(simple.best_temporal.label, "staa");
  EXPECT_EQ(simple.cost_status, CurveStatus::interpolated);
  EXPECT_DOUBLE_EQ(*simple.rmse_vs_supersampling, 0.0006 / 0.003);
  EXPECT_DOUBLE_EQ(*simple.cost_vs_point, 2.5);
  EXPECT_DOUBLE_EQ(*simple.temporal_vs_point, 0.0007 / 0.005);
  const SceneSummary& high = s.scenes[1];
  EXPECT_EQ(high.best_rmse.label, "lean");
  EXPECT_EQ(high.next_rmse.label, "staa");
  EXPECT_TRUE(high.rmse_within_noise);  // 1e-5 apart, the reference's noise 5e-5
  EXPECT_EQ(high.best_temporal.label, "staa");
  EXPECT_EQ(high.cost_status, CurveStatus::below);
  EXPECT_EQ(high.bound_budget, "supersample --samples 1x1x1");
  EXPECT_DOUBLE_EQ(*high.rmse_vs_supersampling, 0.00031 / 0.0066);
  const SceneSummary& sunset = s.scenes[2];
  EXPECT_EQ(sunset.best_rmse.label, "staa");
  EXPECT_EQ(sunset.best_temporal.label, "lean");
  EXPECT_FALSE(sunset.rmse_within_noise);  // the reference's noise unknown
  EXPECT_FALSE(sunset.rmse_vs_supersampling.has_value());
  EXPECT_DOUBLE_EQ(*sunset.cost_vs_point, 3.0);
}

TEST(Summary, InWords) {
  const SummaryText t = summary_text(summarise(hand_made()), md);
  ASSERT_EQ(t.scenes.size(), 3u);
  EXPECT_EQ(t.scenes[0],
            "simple: the lowest RMSE is `staa`'s (0.0006; next `lean`, 0.0008), the lowest "
            "temporal error `staa`'s (0.0007; next `lean`, 0.0009). `staa` takes 5 ms a frame, "
            "2.5 times `point`'s 2 ms, with 0.14 of its temporal error. Supersampling at that "
            "cost (2.5 samples per pixel) reaches RMSE 0.003: `staa`'s is 0.2 of it.");
  EXPECT_EQ(t.scenes[1],
            "high: the lowest RMSE is `lean`'s (0.0003; within the reference's noise, 5e-05, of "
            "`staa`'s 0.00031), the lowest temporal error `staa`'s (0.0004; next `lean`, "
            "0.00045). `staa` takes 2.4 ms a frame, 1.6 times `point`'s 1.5 ms, with 0.044 of "
            "its temporal error. It costs less than the cheapest supersampling budget "
            "(`supersample --samples 1x1x1`, 3 ms, RMSE 0.0066); its RMSE is 0.047 of that "
            "budget's.");
  EXPECT_EQ(t.scenes[2],
            "sunset: the lowest RMSE is `staa`'s (0.004; next `lean`, 0.005), the lowest "
            "temporal error `lean`'s (0.002; next `staa`, 0.003). `staa` takes 9 ms a frame, 3 "
            "times `point`'s 3 ms, with 0.15 of its temporal error.");
  EXPECT_EQ(t.overall,
            "Over the 3 scenes, `staa` has the lowest RMSE on 2 (simple and sunset) and the "
            "lowest temporal error on 2 (simple and high); at equal cost its RMSE is 0.047 to "
            "0.2 of supersampling's; it costs 1.6 to 3 times `point` for 0.044 to 0.15 of its "
            "temporal error.");
}

TEST(Summary, TableOneInWords) {
  const std::vector<std::string> v = paper_table_verdict(hand_made(), md);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0], "In the paper, its method has the lowest RMSE on all four scenes.");
  EXPECT_EQ(v[1],
            "In this study (linear values against our reference, simple and high), the paper's "
            "method (`staa --footprint none --ndf uniform`) beats No AA (`point`) on simple and "
            "high, 32x MSAA (`supersample --samples 6x6x1`) on high; it loses to 32x MSAA "
            "(`supersample --samples 6x6x1`) on simple (0.0014 against 0.0009), LEAN (`lean`) "
            "on simple (0.0014 against 0.0008) and high (0.00035 against 0.0003).");
  EXPECT_EQ(v[2],
            "`staa` has a lower RMSE than every row on simple; it loses on high to LEAN (0.0003) "
            "against its 0.00031.");
}

TEST(Summary, OpensTheReportPage) {
  const std::string page = report_html(hand_made());
  const size_t summary = page.find("<section id=\"summary\">");
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(summary, page.find("<section id=\"table1\">"));  // first, before Table 1
  for (const char* scene : {"simple", "high", "sunset"}) {
    EXPECT_NE(page.find("<li data-scene=\"" + std::string(scene) + "\">"), std::string::npos)
        << scene;
  }
  EXPECT_NE(page.find("<code>staa</code> takes 5 ms a frame, 2.5 times <code>point</code>"),
            std::string::npos);
  EXPECT_NE(page.find("<p class=\"verdict\">In the paper, its method has the lowest RMSE"),
            std::string::npos);
}

}  // namespace
}  // namespace sg
