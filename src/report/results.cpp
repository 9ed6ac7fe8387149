#include "report/results.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "base/error.h"
#include "report/paper.h"
#include "report/summary.h"

namespace sg {
using nlohmann::json;

namespace {

// Numbers that may be infinite (PSNR of identical images) are written as "inf".
json number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}
double number(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
  throw Error("expected a number, got '" + s + "'");
}

json to_json(const RegionMetrics& m) {
  json j = {{"rmse", number(m.rmse)},
            {"psnr", number(m.psnr)},
            {"temporal_error", number(m.temporal_error)},
            {"flicker", number(m.flicker)},
            {"flicker_reference", number(m.flicker_reference)},
            {"pixels", m.pixels},
            {"reference_se", number(m.reference_se)},
            {"rmse_corrected", number(m.rmse_corrected)}};
  if (!m.channels.empty()) {  // colour: {"R": {...}, "G": {...}, "B": {...}}
    j["channels"] = json::object();
    for (size_t c = 0; c < m.channels.size() && c < kChannelNames.size(); ++c) {
      j["channels"][kChannelNames[c]] = {{"rmse", number(m.channels[c].rmse)},
                                         {"temporal_error", number(m.channels[c].temporal_error)},
                                         {"flicker", number(m.channels[c].flicker)}};
    }
  }
  return j;
}
RegionMetrics region_from_json(const json& j) {
  RegionMetrics m;
  m.rmse = number(j.at("rmse"));
  m.psnr = number(j.at("psnr"));
  m.temporal_error = number(j.at("temporal_error"));
  m.flicker = number(j.at("flicker"));
  m.flicker_reference = number(j.at("flicker_reference"));
  m.pixels = j.at("pixels").get<long>();
  // Files from before the reference measured its noise: unknown noise, the RMSE as it is.
  m.reference_se = j.contains("reference_se") ? number(j.at("reference_se"))
                                              : std::numeric_limits<double>::quiet_NaN();
  m.rmse_corrected = j.contains("rmse_corrected") ? number(j.at("rmse_corrected")) : m.rmse;
  if (j.contains("channels")) {
    for (const char* c : kChannelNames) {
      const json& x = j.at("channels").at(c);
      m.channels.push_back(
          {number(x.at("rmse")), number(x.at("temporal_error")), number(x.at("flicker"))});
    }
  }
  return m;
}

json to_json(const ClassFigures& c) {
  return {{"class", c.name},
          {"pixel_share", number(c.pixel_share)},
          {"error_share", number(c.error_share)},
          {"rmse", number(c.rmse)},
          {"temporal_error", number(c.temporal_error)},
          {"reference_se", number(c.reference_se)},
          {"rmse_corrected", number(c.rmse_corrected)},
          {"temporal_corrected", number(c.temporal_corrected)}};
}
ClassFigures class_from_json(const json& j) {
  ClassFigures c;
  c.name = j.at("class").get<std::string>();
  c.pixel_share = number(j.at("pixel_share"));
  c.error_share = number(j.at("error_share"));
  c.rmse = number(j.at("rmse"));
  c.temporal_error = number(j.at("temporal_error"));
  c.reference_se = number(j.at("reference_se"));
  c.rmse_corrected = number(j.at("rmse_corrected"));
  c.temporal_corrected = number(j.at("temporal_corrected"));
  return c;
}

json to_json(const VariantResult& v) {
  json regions = json::object();
  for (size_t k = 0; k < kRegionNames.size(); ++k)
    regions[kRegionNames[k]] = to_json(v.regions[k]);
  json classes = json::array();
  for (const ClassFigures& c : v.classes)
    classes.push_back(to_json(c));
  return {{"label", v.label},
          {"name", v.name},
          {"stateful", v.stateful},
          {"spp", number(v.spp)},
          {"ms_per_frame", number(v.ms_per_frame)},
          {"frames_rendered", v.frames_rendered},
          {"frames_cached", v.frames_cached},
          {"regions", regions},
          {"picture", v.picture},
          {"error_map", v.error_map},
          {"near_crop_picture", v.near_crop_picture},
          {"far_crop_picture", v.far_crop_picture},
          {"trace", v.trace},
          {"classes", classes}};
}
VariantResult variant_from_json(const json& j) {
  VariantResult v;
  v.label = j.at("label").get<std::string>();
  v.name = j.at("name").get<std::string>();
  v.stateful = j.at("stateful").get<bool>();
  v.spp = number(j.at("spp"));
  v.ms_per_frame = number(j.at("ms_per_frame"));
  v.frames_rendered = j.at("frames_rendered").get<int>();
  v.frames_cached = j.at("frames_cached").get<int>();
  for (size_t k = 0; k < kRegionNames.size(); ++k)
    v.regions[k] = region_from_json(j.at("regions").at(kRegionNames[k]));
  v.picture = j.at("picture").get<std::string>();
  v.error_map = j.at("error_map").get<std::string>();
  // Keys added with colour and the report's crops: optional, so older files still read.
  v.near_crop_picture = j.value("near_crop_picture", std::string());
  v.far_crop_picture = j.value("far_crop_picture", std::string());
  if (j.contains("trace")) v.trace = j.at("trace").get<std::vector<double>>();
  if (j.contains("classes")) {
    for (const json& c : j.at("classes"))
      v.classes.push_back(class_from_json(c));
  }
  return v;
}

json to_json(const CropBox& c) {
  return {{"x", c.x}, {"y", c.y}, {"width", c.width}, {"height", c.height}};
}
CropBox crop_from_json(const json& j) {
  return {j.at("x").get<int>(), j.at("y").get<int>(), j.at("width").get<int>(),
          j.at("height").get<int>()};
}

// Interpolated values are numbers; bounds are null.
json maybe(bool ok, double v) {
  return ok ? number(v) : json(nullptr);
}
double maybe(const json& j) {
  return j.is_null() ? 0.0 : number(j);
}

json to_json(const EqualCost& e) {
  const bool c = e.cost.status == CurveStatus::interpolated;
  const bool r = e.rmse.status == CurveStatus::interpolated;
  return {{"target", e.target},
          {"target_ms_per_frame", number(e.target_ms)},
          {"target_rmse", number(e.target_rmse)},
          {"same_cost",
           {{"status", to_string(e.cost.status)},
            {"spp", maybe(c, e.cost.spp)},
            {"rmse", maybe(c, e.cost.rmse)}}},
          {"same_rmse",
           {{"status", to_string(e.rmse.status)},
            {"spp", maybe(r, e.rmse.spp)},
            {"ms_per_frame", maybe(r, e.rmse.ms)},
            {"cost_ratio", maybe(r && e.target_ms > 0, e.rmse.ms / e.target_ms)}}}};
}
EqualCost equal_cost_from_json(const json& j) {
  EqualCost e;
  e.target = j.at("target").get<std::string>();
  e.target_ms = number(j.at("target_ms_per_frame"));
  e.target_rmse = number(j.at("target_rmse"));
  const json& c = j.at("same_cost");
  e.cost.status = curve_status_from_string(c.at("status").get<std::string>());
  e.cost.spp = maybe(c.at("spp"));
  e.cost.rmse = maybe(c.at("rmse"));
  const json& r = j.at("same_rmse");
  e.rmse.status = curve_status_from_string(r.at("status").get<std::string>());
  e.rmse.spp = maybe(r.at("spp"));
  e.rmse.ms = maybe(r.at("ms_per_frame"));
  return e;
}

}  // namespace

std::string results_to_json(const StudyResults& r) {
  const StudySettings& s = r.settings;
  json paper = json::array();
  for (const auto& [row, label] : s.paper_rows)
    paper.push_back({{"row", row}, {"variant", label}});
  json j = {{"schema", "sunglint-results/1"},
            {"settings",
             {{"width", s.width},
              {"height", s.height},
              {"frames", {s.first_frame, s.last_frame}},
              {"fps", number(s.fps)},
              {"reference", s.reference},
              {"methods", s.methods},
              {"budgets", s.budgets},
              {"equal_cost_target", s.equal_cost_target},
              {"exposure", number(s.exposure)},
              {"paper_rows", paper},
              {"command", s.command}}},
            {"scenes", json::array()}};
  for (const SceneResult& sc : r.scenes) {
    json methods = json::array(), budgets = json::array();
    for (const auto& v : sc.methods)
      methods.push_back(to_json(v));
    for (const auto& v : sc.budgets)
      budgets.push_back(to_json(v));
    j["scenes"].push_back({{"name", sc.name},
                           {"file", sc.file},
                           {"shown_frame", sc.shown_frame},
                           {"water_pixels", sc.water_pixels},
                           {"near_pixels", sc.near_pixels},
                           {"far_pixels", sc.far_pixels},
                           {"split_distance", number(sc.split_distance)},
                           {"channels", sc.channels},
                           {"moving_camera", sc.moving_camera},
                           {"cascades", sc.cascades},
                           {"camera_speed", number(sc.camera_speed)},
                           {"camera_turn_deg", number(sc.camera_turn_deg)},
                           {"near_crop", to_json(sc.near_crop)},
                           {"far_crop", to_json(sc.far_crop)},
                           {"error_range", number(sc.error_range)},
                           {"reference", to_json(sc.reference)},
                           {"methods", methods},
                           {"budgets", budgets},
                           {"equal_cost", sc.equal_cost ? to_json(*sc.equal_cost) : json(nullptr)},
                           {"flicker_pixel", sc.flicker_pixel.x < 0
                                                 ? json(nullptr)
                                                 : json{{"x", sc.flicker_pixel.x},
                                                        {"y", sc.flicker_pixel.y},
                                                        {"chosen_by", sc.flicker_pixel.chosen_by}}},
                           {"grid", sc.grid},
                           {"video", sc.video},
                           {"crops", sc.crops}});
  }
  return j.dump(1) + "\n";
}

StudyResults results_from_json(const std::string& text, const std::string& name) {
  StudyResults r;
  try {
    json j = json::parse(text);
    if (j.at("schema") != "sunglint-results/1") {
      throw Error("schema: expected 'sunglint-results/1'");
    }
    const json& s = j.at("settings");
    StudySettings& st = r.settings;
    st.width = s.at("width").get<int>();
    st.height = s.at("height").get<int>();
    st.first_frame = s.at("frames").at(0).get<int>();
    st.last_frame = s.at("frames").at(1).get<int>();
    st.fps = number(s.at("fps"));
    st.reference = s.at("reference").get<std::string>();
    st.methods = s.at("methods").get<std::vector<std::string>>();
    st.budgets = s.at("budgets").get<std::vector<std::string>>();
    st.equal_cost_target = s.at("equal_cost_target").get<std::string>();
    st.exposure = number(s.at("exposure"));
    for (const json& p : s.at("paper_rows"))
      st.paper_rows.emplace_back(p.at("row").get<std::string>(),
                                 p.at("variant").get<std::string>());
    st.command = s.at("command").get<std::string>();
    for (const json& sj : j.at("scenes")) {
      SceneResult sc;
      sc.name = sj.at("name").get<std::string>();
      sc.file = sj.at("file").get<std::string>();
      sc.shown_frame = sj.at("shown_frame").get<int>();
      sc.water_pixels = sj.at("water_pixels").get<long>();
      sc.near_pixels = sj.at("near_pixels").get<long>();
      sc.far_pixels = sj.at("far_pixels").get<long>();
      sc.split_distance = number(sj.at("split_distance"));
      sc.channels = sj.value("channels", 1);
      sc.moving_camera = sj.value("moving_camera", false);  // absent before format /3
      sc.cascades = sj.value("cascades", false);            // absent before cascades
      if (sj.contains("camera_speed")) sc.camera_speed = number(sj.at("camera_speed"));
      if (sj.contains("camera_turn_deg")) sc.camera_turn_deg = number(sj.at("camera_turn_deg"));
      sc.near_crop = crop_from_json(sj.at("near_crop"));
      sc.far_crop = crop_from_json(sj.at("far_crop"));
      sc.error_range = number(sj.at("error_range"));
      sc.reference = variant_from_json(sj.at("reference"));
      for (const json& v : sj.at("methods"))
        sc.methods.push_back(variant_from_json(v));
      for (const json& v : sj.at("budgets"))
        sc.budgets.push_back(variant_from_json(v));
      if (!sj.at("equal_cost").is_null()) sc.equal_cost = equal_cost_from_json(sj.at("equal_cost"));
      sc.grid = sj.at("grid").get<std::string>();
      sc.video = sj.at("video").get<std::string>();
      sc.crops = sj.value("crops", std::string());
      if (sj.contains("flicker_pixel") && !sj.at("flicker_pixel").is_null()) {
        const json& fp = sj.at("flicker_pixel");
        sc.flicker_pixel = {fp.at("x").get<int>(), fp.at("y").get<int>(),
                            fp.at("chosen_by").get<std::string>()};
      }
      r.scenes.push_back(std::move(sc));
    }
  } catch (const json::exception& e) {
    throw Error(name + ": not a sunglint results file: " + e.what());
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  return r;
}

// ------------------------------------------------------------------------------ CSV
namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string g17(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string results_to_csv(const StudyResults& r) {
  std::ostringstream out;
  for (size_t k = 0; k < kCsvColumns.size(); ++k)
    out << (k ? "," : "") << kCsvColumns[k];
  out << "\n";
  auto rows = [&](const SceneResult& sc, const char* kind, const VariantResult& v) {
    for (size_t k = 0; k < kRegionNames.size(); ++k) {
      const RegionMetrics& m = v.regions[k];
      out << csv_field(sc.name) << "," << kind << "," << csv_field(v.label) << ","
          << kRegionNames[k] << "," << g17(m.rmse) << "," << g17(m.psnr) << ","
          << g17(m.temporal_error) << "," << g17(m.flicker) << "," << g17(m.flicker_reference)
          << "," << g17(v.ms_per_frame) << "," << g17(v.spp) << "," << m.pixels << ","
          << v.frames_rendered << "," << v.frames_cached << "," << (v.stateful ? 1 : 0);
      for (int c = 0; c < 3; ++c)
        out << "," << (m.channels.size() == 3 ? g17(m.channels[c].rmse) : "");
      for (int c = 0; c < 3; ++c)
        out << "," << (m.channels.size() == 3 ? g17(m.channels[c].temporal_error) : "");
      out << "\n";
    }
  };
  for (const SceneResult& sc : r.scenes) {
    rows(sc, "reference", sc.reference);
    for (const auto& v : sc.methods)
      rows(sc, "method", v);
    for (const auto& v : sc.budgets)
      rows(sc, "budget", v);
  }
  return out.str();
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  for (size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (k + 1 < text.size() && text[k + 1] == '"') {
        field += '"';
        ++k;
      } else {
        quoted = false;
      }
      continue;
    }
    if (c == '"') {
      if (!field.empty()) throw Error("csv: quote inside an unquoted field");
      quoted = any = true;
    } else if (c == ',') {
      row.push_back(std::move(field));
      field.clear();
      any = true;
    } else if (c == '\n') {
      row.push_back(std::move(field));
      field.clear();
      rows.push_back(std::move(row));
      row.clear();
      any = false;
    } else if (c != '\r') {
      field += c;
      any = true;
    }
  }
  if (quoted) throw Error("csv: unterminated quoted field");
  if (any) {
    row.push_back(std::move(field));
    rows.push_back(std::move(row));
  }
  return rows;
}

// -------------------------------------------------------------------------- Markdown
std::string format_number(const char* format, double v, const std::string& inf_text) {
  if (std::isinf(v)) return v > 0 ? inf_text : "-" + inf_text;
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

namespace {

std::string fmt(const char* f, double v) {
  return format_number(f, v);
}
std::string md_code(const std::string& s) {
  return "`" + s + "`";
}
// An RMSE with the noise-corrected one in brackets (the raw one alone when the
// reference's noise is unknown).
std::string rmse_cell(const RegionMetrics& m) {
  if (!(m.reference_se > 0)) return fmt("%.3g", m.rmse);
  return fmt("%.3g", m.rmse) + " (" + fmt("%.3g", m.rmse_corrected) + ")";
}

}  // namespace

std::string camera_motion_sentence(const SceneResult& sc) {
  if (!sc.moving_camera) return "";
  return "The camera moves (format /3): up to " + format_number("%.3g", sc.camera_speed) +
         " m/s and " + format_number("%.3g", sc.camera_turn_deg) +
         " degrees/s over the frames studied; the near and far halves are those of the first "
         "frame's camera.";
}

std::string reference_noise_text(const SceneResult& sc, const std::string& q) {
  const RegionMetrics &a = sc.reference.at(Region::image), &n = sc.reference.at(Region::near),
                      &f = sc.reference.at(Region::far);
  if (!(a.reference_se >= 0)) {
    return "The reference does not measure its noise: the RMSEs are against it as it is.";
  }
  std::string t =
      "The reference's standard error (its expected RMSE against the exact "
      "image): " +
      fmt("%.3g", a.reference_se) + " (near " + fmt("%.3g", n.reference_se) + ", far " +
      fmt("%.3g", f.reference_se) +
      "). RMSEs are against the reference, the noise-corrected RMSE "
      "sqrt(max(0, RMSE^2 - se^2)) in brackets.";
  if (!(a.reference_se > 0)) {
    // Batches that agree in every pixel measure no noise (cmd_render.cpp says the same of
    // `render`): a rare bright sample that no batch drew would not show in them.
    t += " A standard error of 0: the reference's batches agree in every pixel, so a rare "
         "bright sample that none of them drew (a glint) would not show in it; more samples "
         "or batches in the reference measure it.";
  }
  // Methods whose RMSEs differ by less than the reference's noise.
  std::string close;
  for (size_t x = 0; x < sc.methods.size(); ++x) {
    for (size_t y = x + 1; y < sc.methods.size(); ++y) {
      const double d = sc.methods[x].at(Region::image).rmse - sc.methods[y].at(Region::image).rmse;
      if (std::abs(d) < a.reference_se) {
        close += (close.empty() ? "" : ", ") + q + sc.methods[x].label + q + " and " + q +
                 sc.methods[y].label + q;
      }
    }
  }
  if (!close.empty()) t += " Differences smaller than the reference's noise: " + close + ".";
  return t;
}

namespace {

// Table 1 of the paper beside the study's variants (report/paper.h).
void write_paper_table_markdown(std::ostringstream& o, const StudyResults& r) {
  o << "### Table 1 of Podee et al. (2021) beside ours\n\n"
    << "RMSE, with the ratio to No AA in brackets. The paper measures pictures after glare "
       "and tone mapping, we measure linear values against our own reference: compare the "
       "ratios, not the absolute values.\n\n";
  o << "| paper row | our variant |";
  for (const char* sc : kPaperScenes)
    o << " " << sc << " (paper) | " << sc << " (ours) |";
  o << "\n|---|---|";
  for (size_t k = 0; k < kPaperScenes.size(); ++k)
    o << "---:|---:|";
  o << "\n";
  for (const PaperComparison& c : compare_with_paper(r)) {
    o << "| " << c.method << " | " << (c.label.empty() ? "-" : md_code(c.label)) << " |";
    for (size_t k = 0; k < kPaperScenes.size(); ++k) {
      o << " " << fmt("%.4f", c.paper[k]) << " (" << fmt("%.2f", c.paper_ratio[k]) << ") |";
      if (!c.ours[k]) {
        o << " - |";
        continue;
      }
      o << " " << fmt("%.3g", *c.ours[k]);
      if (c.ours_ratio[k]) o << " (" << fmt("%.2f", *c.ours_ratio[k]) << ")";
      o << " |";
    }
    o << "\n";
  }
}

}  // namespace

// The error split by what the pixel sees (`compare --split`): a row per class that some
// frame has, a column per method.
static void write_class_table_markdown(std::ostringstream& o, const SceneResult& sc) {
  if (sc.methods.empty() || sc.methods.front().classes.empty()) return;
  o << "\nThe error by what the pixel sees (report/pixel_classes.h; each frame's own pixels of "
       "the class). Each cell: RMSE with the reference's noise taken out, the share of the "
       "method's squared error over the image, the temporal error with the reference's "
       "frame-to-frame noise taken out.\n\n| what the pixel sees | pixels |";
  for (const auto& v : sc.methods)
    o << " " << md_code(v.label) << " |";
  o << "\n|---|---:|";
  for (size_t k = 0; k < sc.methods.size(); ++k)
    o << "---:|";
  o << "\n";
  const std::vector<ClassFigures>& first = sc.methods.front().classes;
  for (size_t c = 0; c < first.size(); ++c) {
    if (!(first[c].pixel_share > 0)) continue;
    o << "| " << first[c].name << " | " << fmt("%.1f", 100 * first[c].pixel_share) << "% |";
    for (const auto& v : sc.methods) {
      if (c >= v.classes.size()) {
        o << " - |";
        continue;
      }
      const ClassFigures& x = v.classes[c];
      o << " " << fmt("%.3g", x.rmse_corrected) << ", " << fmt("%.0f", 100 * x.error_share) << "%, "
        << fmt("%.3g", x.temporal_corrected) << " |";
    }
    o << "\n";
  }
}

std::string results_to_markdown(const StudyResults& r, const std::string& prefix) {
  const StudySettings& s = r.settings;
  std::ostringstream o;
  o << "Generated by `sunglint` from `results.json`; do not edit by hand.\n\n";
  if (!s.command.empty()) o << "Command: `" << s.command << "`\n\n";
  o << "Image " << s.width << "x" << s.height << ", frames " << s.first_frame << "-" << s.last_frame
    << ", reference " << md_code(s.reference)
    << ". Metrics on linear pixel values; RMSE and temporal error over all frames, the near "
       "and far halves of the water split at the median distance of the water pixels "
       "(docs/report.md).\n\n";

  const SummaryText summary = summary_text(summarise(r), md_code);
  o << "### Summary\n\n";
  if (!summary.overall.empty()) o << summary.overall << "\n\n";
  for (const std::string& t : summary.scenes)
    o << "- " << t << "\n";
  o << "\n";
  if (studies_a_paper_scene(r)) {
    write_paper_table_markdown(o, r);
    o << "\n";
    for (const std::string& v : paper_table_verdict(r, md_code))
      o << v << "\n\n";
  }

  for (const SceneResult& sc : r.scenes) {
    o << "\n### " << sc.name << "\n\n";
    if (!sc.grid.empty()) {
      o << "![" << sc.name << ": methods side by side](" << prefix << sc.grid << ")\n\n";
      o << "Columns: reference";
      for (const auto& v : sc.methods)
        o << " | " << md_code(v.label);
      o << ". Rows: frame " << sc.shown_frame
        << " after glare and tone mapping (orange box: the near crop, blue box: the far "
           "crop), the near crop zoomed and its difference to the reference, the far crop "
           "zoomed and its difference (linear values; blue: darker, red: brighter, +-"
        << fmt("%.3g", sc.error_range) << " at the ends of the scale in the reference column).\n\n";
    }
    o << "Water: " << sc.water_pixels << " pixels, near half up to "
      << fmt("%.1f", sc.split_distance) << " m. Reference flicker "
      << fmt("%.4g", sc.reference.at(Region::image).flicker) << " (near "
      << fmt("%.4g", sc.reference.at(Region::near).flicker) << ", far "
      << fmt("%.4g", sc.reference.at(Region::far).flicker) << "), "
      << fmt("%.4g", sc.reference.ms_per_frame) << " ms per frame.\n\n";
    if (sc.moving_camera) o << camera_motion_sentence(sc) << "\n\n";
    o << reference_noise_text(sc, "`") << "\n\n";
    o << "| variant | RMSE (corrected) | PSNR (dB) | temporal error | flicker | near RMSE "
         "(corrected) | far RMSE (corrected) | near temporal | far temporal | ms/frame |\n";
    o << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& v : sc.methods) {
      const RegionMetrics &a = v.at(Region::image), &n = v.at(Region::near), &f = v.at(Region::far);
      o << "| " << md_code(v.label) << " | " << rmse_cell(a) << " | " << fmt("%.2f", a.psnr)
        << " | " << fmt("%.3g", a.temporal_error) << " | " << fmt("%.3g", a.flicker) << " | "
        << rmse_cell(n) << " | " << rmse_cell(f) << " | " << fmt("%.3g", n.temporal_error) << " | "
        << fmt("%.3g", f.temporal_error) << " | " << fmt("%.3g", v.ms_per_frame) << " |\n";
    }
    if (sc.channels == 3) {
      o << "\nPer channel (whole image):\n\n| variant | RMSE R | RMSE G | RMSE B | temporal R | "
           "temporal G | temporal B |\n|---|---:|---:|---:|---:|---:|---:|\n";
      for (const auto& v : sc.methods) {
        const auto& ch = v.at(Region::image).channels;
        if (ch.size() != 3) continue;
        o << "| " << md_code(v.label) << " |";
        for (const auto& c : ch)
          o << " " << fmt("%.3g", c.rmse) << " |";
        for (const auto& c : ch)
          o << " " << fmt("%.3g", c.temporal_error) << " |";
        o << "\n";
      }
    }
    if (!sc.crops.empty()) {
      o << "\n![" << sc.name << ": crops at " << kCropScale << ":1](" << prefix << sc.crops
        << ")\n\nCrops at " << kCropScale << ":1 pixels, frame " << sc.shown_frame
        << ": the near crop (left) and the far crop (right) of each column, one row each: "
           "reference";
      for (const auto& v : sc.methods)
        o << ", " << md_code(v.label);
      o << ".\n";
    }
    if (sc.flicker_pixel.x >= 0 && !sc.reference.trace.empty()) {
      o << "\nFlicker at pixel (" << sc.flicker_pixel.x << ", " << sc.flicker_pixel.y << "), where "
        << md_code(sc.flicker_pixel.chosen_by)
        << " has its largest temporal error on the water: its linear value"
        << (sc.channels == 3 ? " (mean of the channels)" : "")
        << " in each frame.\n\n| frame | reference |";
      for (const auto& v : sc.methods)
        o << " " << md_code(v.label) << " |";
      o << "\n|---:|---:|";
      for (size_t k = 0; k < sc.methods.size(); ++k)
        o << "---:|";
      o << "\n";
      for (size_t f = 0; f < sc.reference.trace.size(); ++f) {
        o << "| " << s.first_frame + static_cast<int>(f) << " | "
          << fmt("%.4g", sc.reference.trace[f]) << " |";
        for (const auto& v : sc.methods)
          o << " " << (f < v.trace.size() ? fmt("%.4g", v.trace[f]) : "-") << " |";
        o << "\n";
      }
    }
    if (!sc.budgets.empty()) {
      o << "\nThe supersampling curve (RMSE, the noise-corrected RMSE in brackets):\n\n| budget "
           "| samples per pixel | RMSE | near RMSE | far RMSE | temporal error | ms/frame "
           "|\n|---|---:|---:|---:|---:|---:|---:|\n";
      for (const auto& b : sc.budgets) {
        o << "| " << md_code(b.label) << " | " << fmt("%g", b.spp) << " | "
          << rmse_cell(b.at(Region::image)) << " | " << rmse_cell(b.at(Region::near)) << " | "
          << rmse_cell(b.at(Region::far)) << " | "
          << fmt("%.3g", b.at(Region::image).temporal_error) << " | " << fmt("%.3g", b.ms_per_frame)
          << " |\n";
      }
    }
    if (sc.equal_cost)
      o << "\n" << equal_cost_sentence(*sc.equal_cost, md_code(sc.equal_cost->target)) << "\n";
    write_class_table_markdown(o, sc);
  }
  return o.str();
}

std::string results_summary_markdown(const StudyResults& r, const std::string& picture) {
  std::ostringstream o;
  const StudySettings& s = r.settings;
  if (!picture.empty() && !r.scenes.empty()) {
    const SceneResult& sc = r.scenes.front();
    o << "![" << sc.name << ": every method side by side](" << picture << ")\n\n";
    o << "*" << sc.name << ", frame " << sc.shown_frame << ". Columns: reference";
    for (const auto& v : sc.methods)
      o << " | " << md_code(v.label);
    o << ". Rows: the frame (glare and tone mapping for display only), the near crop zoomed "
         "and its difference to the reference (blue darker, red brighter), the far crop and "
         "its difference.*\n\n";
  }
  o << "RMSE (temporal error) on linear values, " << s.width << "x" << s.height << ", frames "
    << s.first_frame << "-" << s.last_frame << ", reference " << md_code(s.reference)
    << "; where the reference measures its noise, the noise-corrected RMSE follows the RMSE "
       "after a slash:\n\n";
  o << "| variant |";
  for (const auto& sc : r.scenes)
    o << " " << sc.name << " |";
  o << "\n|---|";
  for (size_t k = 0; k < r.scenes.size(); ++k)
    o << "---:|";
  o << "\n";
  for (const auto& label : s.methods) {
    o << "| " << md_code(label) << " |";
    for (const auto& sc : r.scenes) {
      const VariantResult* v = nullptr;
      for (const auto& m : sc.methods) {
        if (m.label == label) v = &m;
      }
      if (v) {
        const RegionMetrics& m = v->at(Region::image);
        o << " " << fmt("%.3g", m.rmse);
        if (m.reference_se > 0) o << " / " << fmt("%.3g", m.rmse_corrected);
        o << " (" << fmt("%.3g", m.temporal_error) << ") |";
      } else {
        o << " - |";
      }
    }
    o << "\n";
  }
  for (const auto& sc : r.scenes) {
    if (sc.equal_cost)
      o << "\n**" << sc.name << "**. "
        << equal_cost_sentence(*sc.equal_cost, md_code(sc.equal_cost->target)) << "\n";
  }
  const SummaryText summary = summary_text(summarise(r), md_code);
  o << "\n**Summary.**";
  if (!summary.overall.empty()) o << " " << summary.overall;
  o << "\n\n";
  for (const std::string& t : summary.scenes)
    o << "- " << t << "\n";
  return o.str();
}

std::string replace_marked_section(const std::string& text, const std::string& begin,
                                   const std::string& end, const std::string& content,
                                   const std::string& name) {
  const size_t b = text.find(begin);
  if (b == std::string::npos) throw Error(name + ": no line '" + begin + "'");
  const size_t body = text.find('\n', b);
  const size_t e = text.find(end, b + begin.size());
  if (body == std::string::npos || e == std::string::npos || e < body) {
    throw Error(name + ": no line '" + end + "' after '" + begin + "'");
  }
  std::string c = content;
  if (!c.empty() && c.back() != '\n') c += '\n';
  return text.substr(0, body + 1) + c + text.substr(e);
}

std::string equal_cost_sentence(const EqualCost& e, const std::string& target_markup) {
  std::string t = "Equal cost, target " + target_markup + " (" + fmt("%.3g", e.target_ms) +
                  " ms per frame, RMSE " + fmt("%.3g", e.target_rmse) + "): ";
  switch (e.cost.status) {
    case CurveStatus::interpolated:
      t += "supersampling at the same cost takes " + fmt("%.3g", e.cost.spp) +
           " samples per pixel and reaches RMSE " + fmt("%.3g", e.cost.rmse) + "; ";
      break;
    case CurveStatus::below:
      t += "it costs less than the cheapest supersampling budget; ";
      break;
    case CurveStatus::above:
      t += "it costs more than the largest supersampling budget; ";
      break;
  }
  switch (e.rmse.status) {
    case CurveStatus::interpolated:
      t += "supersampling needs " + fmt("%.3g", e.rmse.spp) + " samples per pixel (" +
           fmt("%.3g", e.rmse.ms) + " ms per frame, " + fmt("%.3g", e.rmse.ms / e.target_ms) +
           "x its time) to match its RMSE.";
      break;
    case CurveStatus::below:
      t += "the cheapest supersampling budget already matches its RMSE.";
      break;
    case CurveStatus::above:
      t += "no supersampling budget of the curve matches its RMSE.";
      break;
  }
  return t;
}

}  // namespace sg
