// results.json and results.csv round-trip and hold every scene, variant, region and metric;
// the Markdown and the README section are generated from them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "base/error.h"
#include "report/paper.h"
#include "report/results.h"

namespace sg {
namespace {

VariantResult variant(const std::string& label, const std::string& name, double seed) {
  VariantResult v;
  v.label = label;
  v.name = name;
  v.stateful = seed > 2;
  v.spp = name == "supersample" ? 4 : 0;
  v.ms_per_frame = 1.0 / 3.0 + seed;
  v.frames_rendered = 3;
  v.frames_cached = 7;
  for (int k = 0; k < 4; ++k) {
    RegionMetrics& m = v.regions[k];
    m.rmse = 0.01 * (seed + 1) / (k + 1) + 1e-17;
    m.psnr = -20 * std::log10(m.rmse);
    m.temporal_error = m.rmse / 7;
    m.flicker = m.rmse / 11;
    m.flicker_reference = m.rmse / 13;
    m.pixels = 1000 - k;
  }
  v.picture = "img/x/" + name + ".png";
  v.error_map = "img/x/" + name + "-error.png";
  return v;
}

StudyResults sample() {
  StudyResults r;
  StudySettings& s = r.settings;
  s.width = 32;
  s.height = 18;
  s.first_frame = 2;
  s.last_frame = 5;
  s.fps = 30;
  s.reference = "reference --samples 4x4x2";
  s.methods = {"point", "supersample --samples 2x2x1", "odd, \"label\""};
  s.budgets = {"supersample --samples 1x1x1", "supersample --samples 2x2x1"};
  s.equal_cost_target = "point";
  s.exposure = 3;
  s.paper_rows = {{"No AA", "point"}};
  s.command = "sunglint compare ...";
  for (const char* name : {"simple", "high"}) {
    SceneResult sc;
    sc.name = name;
    sc.file = std::string("scenes/") + name + ".json";
    sc.shown_frame = 5;
    sc.water_pixels = 300;
    sc.near_pixels = 150;
    sc.far_pixels = 150;
    sc.split_distance = 12.25;
    sc.near_crop = {1, 2, 8, 4};
    sc.far_crop = {3, 4, 8, 4};
    sc.error_range = 0.125;
    sc.reference = variant(s.reference, "reference", 0);
    sc.reference.regions[0].rmse = 0;
    sc.reference.regions[0].psnr = INFINITY;
    sc.methods = {variant("point", "point", 1),
                  variant("supersample --samples 2x2x1", "supersample", 2),
                  variant("odd, \"label\"", "point", 3)};
    sc.budgets = {variant("supersample --samples 1x1x1", "supersample", 4),
                  variant("supersample --samples 2x2x1", "supersample", 5)};
    EqualCost e;
    e.target = "point";
    e.target_ms = 1.5;
    e.target_rmse = 0.02;
    e.cost = {CurveStatus::interpolated, 2.5, 0.03};
    e.rmse = {CurveStatus::above, 0, 0};
    sc.equal_cost = e;
    sc.grid = std::string("img/") + name + "-grid.png";
    sc.video = std::string("video/") + name + ".mp4";
    sc.crops = std::string("img/") + name + "-crops.png";
    sc.flicker_pixel = {7, 3, "point"};
    for (VariantResult* v : {&sc.reference, &sc.methods[0], &sc.methods[1], &sc.methods[2]}) {
      v->near_crop_picture = "img/x/" + v->name + "-near.png";
      v->far_crop_picture = "img/x/" + v->name + "-far.png";
      v->trace = {0.125, 0.5 + v->ms_per_frame, 1.0 / 3.0, 0.0};
    }
    // The error split by what the pixel sees (compare --split), on the methods.
    for (VariantResult& v : sc.methods) {
      v.classes.push_back({"nearer crest", 0.125, 0.25, 1e-3, 2e-3, 1e-4, 9.9e-4, 1.99e-3});
      v.classes.push_back({"plain", 0.5, 0.75, 5e-4 + v.ms_per_frame * 1e-6, 4e-4, 1e-4, 4.9e-4,
                           std::numeric_limits<double>::quiet_NaN()});
    }
    r.scenes.push_back(sc);
  }
  r.scenes[1].equal_cost.reset();
  // The second scene is in colour: per-channel figures.
  SceneResult& c = r.scenes[1];
  c.channels = 3;
  for (VariantResult* v : {&c.reference, &c.methods[0], &c.methods[1], &c.methods[2]}) {
    for (RegionMetrics& m : v->regions) {
      for (int k = 0; k < 3; ++k)
        m.channels.push_back({m.rmse * (k + 1) / 3.0, m.temporal_error / (k + 2), m.flicker * k});
    }
  }
  return r;
}

void expect_same(const VariantResult& a, const VariantResult& b) {
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.stateful, b.stateful);
  EXPECT_EQ(a.spp, b.spp);
  EXPECT_EQ(a.ms_per_frame, b.ms_per_frame);
  EXPECT_EQ(a.frames_rendered, b.frames_rendered);
  EXPECT_EQ(a.frames_cached, b.frames_cached);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(a.regions[k].rmse, b.regions[k].rmse);
    EXPECT_EQ(a.regions[k].psnr, b.regions[k].psnr);
    EXPECT_EQ(a.regions[k].temporal_error, b.regions[k].temporal_error);
    EXPECT_EQ(a.regions[k].flicker, b.regions[k].flicker);
    EXPECT_EQ(a.regions[k].flicker_reference, b.regions[k].flicker_reference);
    EXPECT_EQ(a.regions[k].pixels, b.regions[k].pixels);
  }
  EXPECT_EQ(a.picture, b.picture);
  EXPECT_EQ(a.error_map, b.error_map);
  EXPECT_EQ(a.near_crop_picture, b.near_crop_picture);
  EXPECT_EQ(a.far_crop_picture, b.far_crop_picture);
  EXPECT_EQ(a.trace, b.trace);
  ASSERT_EQ(a.classes.size(), b.classes.size());
  for (size_t c = 0; c < a.classes.size(); ++c) {
    const ClassFigures &x = a.classes[c], &y = b.classes[c];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.pixel_share, y.pixel_share);
    EXPECT_EQ(x.error_share, y.error_share);
    EXPECT_EQ(x.rmse, y.rmse);
    EXPECT_EQ(x.temporal_error, y.temporal_error);
    EXPECT_EQ(x.reference_se, y.reference_se);
    EXPECT_EQ(x.rmse_corrected, y.rmse_corrected);
    EXPECT_EQ(std::isnan(x.temporal_corrected), std::isnan(y.temporal_corrected));
    if (!std::isnan(x.temporal_corrected)) {
      EXPECT_EQ(x.temporal_corrected, y.temporal_corrected);
    }
  }
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(a.regions[k].channels.size(), b.regions[k].channels.size());
    for (size_t c = 0; c < a.regions[k].channels.size(); ++c) {
      EXPECT_EQ(a.regions[k].channels[c].rmse, b.regions[k].channels[c].rmse);
      EXPECT_EQ(a.regions[k].channels[c].temporal_error, b.regions[k].channels[c].temporal_error);
      EXPECT_EQ(a.regions[k].channels[c].flicker, b.regions[k].channels[c].flicker);
    }
  }
}

TEST(Results, JsonRoundTrips) {
  const StudyResults r = sample();
  const std::string text = results_to_json(r);
  const StudyResults b = results_from_json(text, "results.json");
  EXPECT_EQ(results_to_json(b), text);
  EXPECT_EQ(b.settings.methods, r.settings.methods);
  EXPECT_EQ(b.settings.paper_rows, r.settings.paper_rows);
  ASSERT_EQ(b.scenes.size(), 2u);
  for (size_t s = 0; s < 2; ++s) {
    const SceneResult &x = r.scenes[s], &y = b.scenes[s];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.split_distance, y.split_distance);
    EXPECT_EQ(x.far_crop.x, y.far_crop.x);
    expect_same(x.reference, y.reference);
    ASSERT_EQ(x.methods.size(), y.methods.size());
    for (size_t m = 0; m < x.methods.size(); ++m)
      expect_same(x.methods[m], y.methods[m]);
    ASSERT_EQ(x.budgets.size(), y.budgets.size());
    EXPECT_EQ(x.equal_cost.has_value(), y.equal_cost.has_value());
    EXPECT_EQ(x.channels, y.channels);
    EXPECT_EQ(x.crops, y.crops);
    EXPECT_EQ(x.flicker_pixel.x, y.flicker_pixel.x);
    EXPECT_EQ(x.flicker_pixel.y, y.flicker_pixel.y);
    EXPECT_EQ(x.flicker_pixel.chosen_by, y.flicker_pixel.chosen_by);
  }
  EXPECT_EQ(b.scenes[1].methods[0].regions[2].channels.size(), 3u);
  EXPECT_TRUE(b.scenes[0].methods[0].regions[2].channels.empty());
  EXPECT_TRUE(std::isinf(b.scenes[0].reference.regions[0].psnr));
  EXPECT_EQ(b.scenes[0].equal_cost->cost.spp, 2.5);
  EXPECT_EQ(b.scenes[0].equal_cost->rmse.status, CurveStatus::above);
  EXPECT_THROW(results_from_json("{}", "x.json"), Error);
  EXPECT_THROW(results_from_json("not json", "x.json"), Error);
}

// A results.json written before colour, crops and the flicker plot still reads.
TEST(Results, FilesWithoutTheColourKeysRead) {
  StudyResults r = sample();
  r.scenes.pop_back();  // the grey scene only
  nlohmann::json j = nlohmann::json::parse(results_to_json(r));
  std::function<void(nlohmann::json&)> strip = [&](nlohmann::json& x) {
    if (x.is_object()) {
      for (const char* key : {"channels", "crops", "flicker_pixel", "trace", "near_crop_picture",
                              "far_crop_picture", "classes"})
        x.erase(key);
    }
    if (x.is_structured()) {
      for (auto& y : x)
        strip(y);
    }
  };
  strip(j);
  const std::string text = j.dump(1);
  for (const char* key : {"channels", "crops", "flicker_pixel", "trace", "crop_picture", "classes"})
    ASSERT_EQ(text.find(key), std::string::npos) << key;
  const StudyResults b = results_from_json(text, "old.json");
  EXPECT_EQ(b.scenes[0].channels, 1);
  EXPECT_TRUE(b.scenes[0].crops.empty());
  EXPECT_EQ(b.scenes[0].flicker_pixel.x, -1);
  EXPECT_TRUE(b.scenes[0].methods[0].trace.empty());
  EXPECT_TRUE(b.scenes[0].methods[0].classes.empty());
  EXPECT_EQ(b.scenes[0].methods[0].regions[0].rmse, r.scenes[0].methods[0].regions[0].rmse);
}

TEST(Results, CsvHoldsEverySceneVariantRegionAndMetric) {
  const StudyResults r = sample();
  const auto rows = parse_csv(results_to_csv(r));
  ASSERT_FALSE(rows.empty());
  const auto& head = rows.front();
  ASSERT_EQ(head.size(), kCsvColumns.size());
  for (size_t k = 0; k < kCsvColumns.size(); ++k)
    EXPECT_EQ(head[k], kCsvColumns[k]);
  // 2 scenes x (reference + 3 methods + 2 budgets) x 4 regions.
  EXPECT_EQ(rows.size(), 1u + 2 * 6 * 4);
  std::set<std::string> seen;
  for (size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ASSERT_EQ(row.size(), head.size());
    seen.insert(row[0] + "|" + row[1] + "|" + row[2] + "|" + row[3]);
    // Values round-trip exactly.
    const SceneResult& sc = r.scenes[row[0] == "simple" ? 0 : 1];
    const VariantResult* v = nullptr;
    if (row[1] == "reference") v = &sc.reference;
    for (const auto& m : row[1] == "budget" ? sc.budgets : sc.methods) {
      if (row[1] != "reference" && m.label == row[2]) v = &m;
    }
    ASSERT_NE(v, nullptr) << row[2];
    int region = -1;
    for (int k = 0; k < 4; ++k) {
      if (row[3] == kRegionNames[k]) region = k;
    }
    ASSERT_GE(region, 0);
    const RegionMetrics& m = v->regions[region];
    EXPECT_EQ(std::stod(row[4]), m.rmse);
    EXPECT_EQ(std::stod(row[5]), m.psnr);
    EXPECT_EQ(std::stod(row[6]), m.temporal_error);
    EXPECT_EQ(std::stod(row[7]), m.flicker);
    EXPECT_EQ(std::stod(row[8]), m.flicker_reference);
    EXPECT_EQ(std::stod(row[9]), v->ms_per_frame);
    EXPECT_EQ(std::stol(row[11]), m.pixels);
    // Per-channel columns: numbers for the colour scene, empty for the grey one.
    for (int c = 0; c < 3; ++c) {
      if (m.channels.empty()) {
        EXPECT_EQ(row[15 + c], "");
        EXPECT_EQ(row[18 + c], "");
      } else {
        EXPECT_EQ(std::stod(row[15 + c]), m.channels[c].rmse);
        EXPECT_EQ(std::stod(row[18 + c]), m.channels[c].temporal_error);
      }
    }
  }
  for (const auto& sc : r.scenes) {
    for (const auto& v : sc.methods) {
      for (const char* region : kRegionNames)
        EXPECT_TRUE(seen.count(sc.name + "|method|" + v.label + "|" + region)) << v.label;
    }
  }
  EXPECT_THROW(parse_csv("a,\"b"), Error);
}

TEST(Results, MarkdownAndReadmeSection) {
  const StudyResults r = sample();
  const std::string md = results_to_markdown(r, "../out/");
  for (const auto& sc : r.scenes) {
    EXPECT_NE(md.find("### " + sc.name), std::string::npos);
    EXPECT_NE(md.find("](../out/" + sc.grid + ")"), std::string::npos);
  }
  EXPECT_NE(md.find("`supersample --samples 2x2x1`"), std::string::npos);
  EXPECT_NE(md.find("| No AA | `point` | 0.0797 (1.00) |"), std::string::npos);
  EXPECT_NE(md.find("reaches RMSE 0.03"), std::string::npos);
  // Crops, the flicker table (one row per frame), the colour scene's per-channel table.
  EXPECT_NE(md.find("](../out/img/high-crops.png)"), std::string::npos);
  EXPECT_NE(md.find("Flicker at pixel (7, 3), where `point`"), std::string::npos);
  EXPECT_NE(md.find("| 3 | 0.8333 | 1.833 | 2.833 | 3.833 |"), std::string::npos);
  EXPECT_EQ(md.find("Per channel"), md.rfind("Per channel"));  // the colour scene only
  // The split by what the pixel sees: a row per class, a cell per method.
  EXPECT_NE(md.find("| nearer crest | 12.5% | 0.00099, 25%, 0.00199 |"), std::string::npos);
  EXPECT_GT(md.find("Per channel"), md.find("### high"));

  const std::string readme = "intro\n<!-- demo:begin -->\nold\nold\n<!-- demo:end -->\nrest\n";
  const std::string filled = replace_marked_section(readme, "<!-- demo:begin -->",
                                                    "<!-- demo:end -->", "new", "README.md");
  EXPECT_EQ(filled, "intro\n<!-- demo:begin -->\nnew\n<!-- demo:end -->\nrest\n");
  EXPECT_EQ(replace_marked_section(filled, "<!-- demo:begin -->", "<!-- demo:end -->", "new",
                                   "README.md"),
            filled);
  EXPECT_THROW(replace_marked_section("x", "<!-- demo:begin -->", "<!-- demo:end -->", "", "R"),
               Error);
  // Table 1 only beside a study of the paper's scenes.
  EXPECT_NE(md.find("### Table 1 of Podee"), std::string::npos);
  StudyResults other = r;
  for (SceneResult& sc : other.scenes)
    sc.name = "sea-" + sc.name;
  EXPECT_EQ(results_to_markdown(other, "../out/").find("Table 1"), std::string::npos);
  EXPECT_FALSE(studies_a_paper_scene(other));
  EXPECT_TRUE(studies_a_paper_scene(r));
  const std::string summary = results_summary_markdown(r, "docs/img/simple-grid.png");
  EXPECT_NE(summary.find("![simple"), std::string::npos);
  EXPECT_NE(summary.find("| `point` |"), std::string::npos);
}

// A reference whose batches agree in every pixel (standard error 0) measured no noise: the
// report says so, where a measured or unknown noise gets no such sentence.
TEST(Results, AReferenceStandardErrorOfZeroIsSaidToMeasureNoNoise) {
  SceneResult sc = sample().scenes[0];
  auto text_with = [&](double se) {
    for (RegionMetrics& m : sc.reference.regions)
      m.reference_se = se;
    return reference_noise_text(sc, "`");
  };
  const std::string said = "A standard error of 0: the reference's batches agree in every pixel";
  EXPECT_NE(text_with(0.0).find(said), std::string::npos);
  EXPECT_EQ(text_with(2e-4).find(said), std::string::npos);
  EXPECT_NE(text_with(2e-4).find("standard error (its expected RMSE"), std::string::npos);
  EXPECT_EQ(text_with(std::numeric_limits<double>::quiet_NaN()).find(said), std::string::npos);
}

TEST(Paper, RowsMatchVariantsAndRatiosCompare) {
  const auto m = match_paper_rows(
      {"point", "supersample --samples 6x6x1", "staa", "staa --footprint none --ndf uniform"}, {});
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0], (std::pair<std::string, std::string>{"No AA", "point"}));
  // The paper's method is `--footprint none`: plain `staa` (with the footprint term) is not
  // matched to the paper's rows.
  EXPECT_EQ(m[2], (std::pair<std::string, std::string>{"Ours (uniform)",
                                                       "staa --footprint none --ndf uniform"}));
  const auto o = match_paper_rows({"point", "lean --x 1"}, {{"LEAN", "lean  --x 1"}});
  EXPECT_EQ(o[1], (std::pair<std::string, std::string>{"LEAN", "lean --x 1"}));
  EXPECT_THROW(match_paper_rows({"point"}, {{"Nope", "point"}}), Error);
  EXPECT_THROW(match_paper_rows({"point"}, {{"LEAN", "lean"}}), Error);

  StudyResults r = sample();
  r.settings.paper_rows = {{"No AA", "point"}, {"32x MSAA", "supersample --samples 2x2x1"}};
  const auto c = compare_with_paper(r);
  ASSERT_EQ(c.size(), paper_table1().size());
  EXPECT_NEAR(c[1].paper_ratio[0], 0.0795 / 0.0797, 1e-12);
  ASSERT_TRUE(c[1].ours[0] && c[1].ours_ratio[0]);
  EXPECT_NEAR(*c[1].ours_ratio[0],
              r.scenes[0].methods[1].regions[0].rmse / r.scenes[0].methods[0].regions[0].rmse,
              1e-12);
  EXPECT_FALSE(c[1].ours[1]);  // the study has no "smooth" scene
  EXPECT_FALSE(c[2].ours[0]);  // nor a LEAN variant
}

}  // namespace
}  // namespace sg
