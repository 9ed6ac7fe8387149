#include "report/html.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "base/atomic_file.h"
#include "report/assets.h"
#include "report/cache.h"
#include "report/paper.h"
#include "report/results.h"
#include "report/summary.h"
#include "report/video.h"

namespace sg {
namespace fs = std::filesystem;

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

namespace {

std::string fmt(const char* f, double v) {
  return format_number(f, v, "&infin;");
}
std::string code(const std::string& s) {
  return "<code>" + html_escape(s) + "</code>";
}
// An RMSE with the noise-corrected one below it, small.
std::string rmse_cell(const RegionMetrics& m) {
  if (!(m.reference_se > 0)) return fmt("%.3g", m.rmse);
  return fmt("%.3g", m.rmse) + " <small>(" + fmt("%.3g", m.rmse_corrected) + ")</small>";
}

// Equal-width labels above a picture or video whose columns are equal.
std::string column_labels(const SceneResult& sc) {
  std::string o = "<div class=\"cols\" style=\"--cols:" + std::to_string(sc.methods.size() + 1) +
                  "\"><span>reference</span>";
  for (const auto& v : sc.methods)
    o += "<span>" + html_escape(v.label) + "</span>";
  return o + "</div>\n";
}

// The opening summary, from the results alone (report/summary.h).
std::string summary_section(const StudyResults& r) {
  const SummaryText t = summary_text(summarise(r), code);
  std::ostringstream o;
  o << "<section id=\"summary\"><h2>Summary</h2>\n";
  if (!t.overall.empty()) o << "<p class=\"overall\">" << t.overall << "</p>\n";
  o << "<ul>\n";
  for (size_t k = 0; k < t.scenes.size() && k < r.scenes.size(); ++k) {
    o << "<li data-scene=\"" << html_escape(r.scenes[k].name) << "\"><a href=\"#scene-"
      << file_slug(r.scenes[k].name) << "\">" << html_escape(r.scenes[k].name) << "</a>"
      << t.scenes[k].substr(r.scenes[k].name.size()) << "</li>\n";
  }
  o << "</ul>\n<p class=\"hint\">Whole-image RMSE and temporal error on linear values "
       "against the reference; equal cost on the supersampling curve of each scene "
       "(definitions at the end).</p></section>\n";
  return o.str();
}

std::string paper_table(const StudyResults& r) {
  std::ostringstream o;
  o << "<table class=\"num\"><thead><tr><th rowspan=\"2\">paper row</th><th rowspan=\"2\">our "
       "variant</th>";
  for (const char* s : kPaperScenes)
    o << "<th colspan=\"2\">" << s << "</th>";
  o << "</tr><tr>";
  for (size_t k = 0; k < kPaperScenes.size(); ++k)
    o << "<th>paper</th><th>ours</th>";
  o << "</tr></thead><tbody>\n";
  for (const PaperComparison& c : compare_with_paper(r)) {
    o << "<tr><th>" << html_escape(c.method) << "</th><td>"
      << (c.label.empty() ? "&ndash;" : code(c.label)) << "</td>";
    for (size_t k = 0; k < kPaperScenes.size(); ++k) {
      o << "<td>" << fmt("%.4f", c.paper[k]) << " <small>(" << fmt("%.2f", c.paper_ratio[k])
        << ")</small></td><td>";
      if (c.ours[k]) {
        o << fmt("%.3g", *c.ours[k]);
        if (c.ours_ratio[k]) o << " <small>(" << fmt("%.2f", *c.ours_ratio[k]) << ")</small>";
      } else {
        o << "&ndash;";
      }
      o << "</td>";
    }
    o << "</tr>\n";
  }
  o << "</tbody></table>\n";
  return o.str();
}

std::string scene_table(const SceneResult& sc) {
  std::ostringstream o;
  o << "<table class=\"num\"><thead><tr><th rowspan=\"2\">variant</th><th colspan=\"4\">whole "
       "image</th><th colspan=\"2\">near half of the water</th><th colspan=\"2\">far "
       "half</th><th rowspan=\"2\">ms per frame</th></tr>"
       "<tr><th>RMSE</th><th>PSNR (dB)</th><th>temporal error</th><th>flicker</th>"
       "<th>RMSE</th><th>temporal error</th><th>RMSE</th><th>temporal error</th></tr></thead>"
       "<tbody>\n";
  auto row = [&](const VariantResult& v, bool reference) {
    const RegionMetrics &a = v.at(Region::image), &n = v.at(Region::near), &f = v.at(Region::far);
    o << "<tr" << (reference ? " class=\"ref\"" : "") << "><th>" << code(v.label) << "</th>";
    if (reference) {
      o << "<td>&ndash;</td><td>&ndash;</td><td>&ndash;</td><td>" << fmt("%.3g", a.flicker)
        << "</td><td>&ndash;</td><td>&ndash;</td><td>&ndash;</td><td>&ndash;</td>";
    } else {
      o << "<td>" << rmse_cell(a) << "</td><td>" << fmt("%.2f", a.psnr) << "</td><td>"
        << fmt("%.3g", a.temporal_error) << "</td><td>" << fmt("%.3g", a.flicker) << "</td><td>"
        << rmse_cell(n) << "</td><td>" << fmt("%.3g", n.temporal_error) << "</td><td>"
        << rmse_cell(f) << "</td><td>" << fmt("%.3g", f.temporal_error) << "</td>";
    }
    o << "<td>" << fmt("%.3g", v.ms_per_frame) << "</td></tr>\n";
  };
  row(sc.reference, true);
  for (const auto& v : sc.methods)
    row(v, false);
  o << "</tbody></table>\n<p>" << html_escape(reference_noise_text(sc, "'")) << "</p>\n";
  return o.str();
}

// Colour: RMSE and temporal error of each channel, whole image.
std::string channel_table(const SceneResult& sc) {
  std::ostringstream o;
  o << "<table class=\"num channels\"><thead><tr><th rowspan=\"2\">variant</th><th "
       "colspan=\"3\">RMSE</th><th colspan=\"3\">temporal error</th></tr><tr>";
  for (int k = 0; k < 2; ++k) {
    for (const char* c : kChannelNames)
      o << "<th>" << c << "</th>";
  }
  o << "</tr></thead><tbody>\n";
  for (const auto& v : sc.methods) {
    const auto& ch = v.at(Region::image).channels;
    if (ch.size() != 3) continue;
    o << "<tr><th>" << code(v.label) << "</th>";
    for (const auto& c : ch)
      o << "<td>" << fmt("%.3g", c.rmse) << "</td>";
    for (const auto& c : ch)
      o << "<td>" << fmt("%.3g", c.temporal_error) << "</td>";
    o << "</tr>\n";
  }
  o << "</tbody></table>\n";
  return o.str();
}

// Every column's near and far crops at kCropScale:1 pixels, shown at their own size.
std::string crops_table(const SceneResult& sc) {
  if (sc.reference.near_crop_picture.empty()) return "";
  std::ostringstream o;
  o << "<h3>Crops at " << kCropScale << ":1</h3>\n<p>Frame " << sc.shown_frame
    << ", each pixel shown as " << kCropScale << "&times;" << kCropScale
    << " screen pixels (never shrunk): the near crop (" << sc.near_crop.width << "&times;"
    << sc.near_crop.height << " pixels at " << sc.near_crop.x << ", " << sc.near_crop.y
    << ") and the far crop (at " << sc.far_crop.x << ", " << sc.far_crop.y
    << "), where the reference's glitter is brightest.</p>\n<div class=\"crops\"><table>"
       "<thead><tr><th>variant</th><th>near</th><th>far</th></tr></thead><tbody>\n";
  auto row = [&](const VariantResult& v, const std::string& label) {
    const int w = sc.near_crop.width * kCropScale, h = sc.near_crop.height * kCropScale;
    o << "<tr><th>" << label << "</th>";
    for (const std::string* pic : {&v.near_crop_picture, &v.far_crop_picture}) {
      o << "<td><img class=\"crop\" src=\"" << html_escape(*pic) << "\" width=\"" << w
        << "\" height=\"" << h << "\" alt=\"" << html_escape(v.label) << "\"></td>";
    }
    o << "</tr>\n";
  };
  row(sc.reference, "reference");
  for (const auto& v : sc.methods) {
    if (!v.near_crop_picture.empty()) row(v, code(v.label));
  }
  o << "</tbody></table></div>\n";
  return o.str();
}

// The flicker plot: one pixel's value over the frames, reference against methods.
std::string flicker_section(const SceneResult& sc) {
  if (sc.flicker_pixel.x < 0 || sc.reference.trace.empty()) return "";
  std::ostringstream o;
  o << "<h3>Flicker at one pixel</h3>\n<p>The value of pixel (" << sc.flicker_pixel.x << ", "
    << sc.flicker_pixel.y << ") in each frame"
    << (sc.channels == 3 ? " (the mean of its channels)" : "")
    << ", linear: the pixel of the water where " << code(sc.flicker_pixel.chosen_by)
    << " has its largest temporal error. The reference is the black line; a method that "
       "flickers jumps where it does not.</p>\n"
    << "<div class=\"chart flicker\"><canvas id=\"chart-flicker-" << file_slug(sc.name)
    << "\" data-scene=\"" << html_escape(sc.name) << "\"></canvas></div>\n";
  return o.str();
}

// A URL query value: every byte but unreserved ones (RFC 3986) as %XX.
std::string url_escape(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += "0123456789ABCDEF"[c >> 4];
      out += "0123456789ABCDEF"[c & 15];
    }
  }
  return out;
}

std::string scene_section(const SceneResult& sc, const StudyResults& r) {
  const std::string id = "scene-" + file_slug(sc.name);
  std::ostringstream o;
  o << "<section id=\"" << id << "\"><h2>" << html_escape(sc.name) << "</h2>\n";
  o << "<p>" << html_escape(sc.file) << ": " << sc.water_pixels
    << " pixels see water; the near half reaches " << fmt("%.1f", sc.split_distance)
    << " m from the camera. Reference flicker: whole image "
    << fmt("%.3g", sc.reference.at(Region::image).flicker) << ", near "
    << fmt("%.3g", sc.reference.at(Region::near).flicker) << ", far "
    << fmt("%.3g", sc.reference.at(Region::far).flicker) << ".</p>\n";
  if (sc.moving_camera)
    o << "<p class=\"camera\">" << html_escape(camera_motion_sentence(sc)) << "</p>\n";
  // The live page `compare` writes beside the report (web/web_page.h, docs/web.md); it
  // renders fixed cameras and explicit waves only.
  if (!sc.moving_camera && !sc.cascades) {
    o << "<p class=\"live\"><a href=\"web/index.html?scene=" << html_escape(url_escape(sc.name))
      << "&amp;method=staa&amp;split=point\">" << html_escape(sc.name)
      << " live in the browser</a>: staa | point, the kernel as WebGL 2 shaders (sunglint "
         "web)</p>\n";
  }
  o << scene_table(sc);
  if (sc.equal_cost) {
    o << "<p class=\"equal-cost\">"
      << equal_cost_sentence(*sc.equal_cost, code(sc.equal_cost->target)) << "</p>\n";
  }
  if (!sc.budgets.empty()) {
    o << "<div class=\"chart\"><canvas id=\"chart-cost-" << file_slug(sc.name) << "\" data-scene=\""
      << html_escape(sc.name) << "\"></canvas></div>\n";
  }
  if (sc.channels == 3) o << channel_table(sc);
  o << crops_table(sc);  // first: every column's glints at 2:1, labelled
  if (!sc.grid.empty()) {
    o << "<h3>Frame " << sc.shown_frame << ", every column</h3>\n<figure class=\"grid\">"
      << column_labels(sc) << "<img src=\"" << html_escape(sc.grid) << "\" alt=\""
      << html_escape(sc.name)
      << ": every method side by side\">\n<figcaption>Rows: the frame after glare and tone "
         "mapping (orange box: the near crop, blue box: the far crop); the near crop zoomed "
         "and its difference to the reference; the far crop zoomed and its difference. "
         "Differences are on linear values (blue: darker than the reference, red: brighter, "
         "&plusmn;"
      << fmt("%.3g", sc.error_range)
      << " at the ends of the scale shown in the reference column).</figcaption></figure>\n";
  }
  o << flicker_section(sc);
  if (!sc.reference.picture.empty() && !sc.methods.empty()) {
    o << "<h3>Reference against a method</h3>\n<div class=\"slider\"><label>method <select>";
    for (const auto& v : sc.methods) {
      o << "<option value=\"" << html_escape(v.picture) << "\">" << html_escape(v.label)
        << "</option>";
    }
    o << "</select></label><div class=\"compare\"><img class=\"under\" src=\""
      << html_escape(sc.reference.picture) << "\" alt=\"reference\"><img class=\"over\" src=\""
      << html_escape(sc.methods.front().picture)
      << "\" alt=\"method\"><input type=\"range\" min=\"0\" max=\"100\" value=\"50\" "
         "aria-label=\"split\"></div><p class=\"hint\">left: the method, right: the "
         "reference; drag to move the split.</p></div>\n";
  }
  if (!sc.video.empty()) {
    const int frames = r.settings.last_frame - r.settings.first_frame + 1;
    const double fps = playback_fps(r.settings.fps, frames);
    o << "<h3>Frames " << r.settings.first_frame << "&ndash;" << r.settings.last_frame
      << "</h3>\n<figure class=\"video\">" << column_labels(sc) << "<video src=\""
      << html_escape(sc.video)
      << "\" controls autoplay muted loop playsinline preload=\"auto\"></video>"
         "<figcaption>Top: the frames; bottom: the near crop zoomed. Flicker shows as pixels "
         "that blink from frame to frame. "
      << frames << " frames at " << fmt("%.3g", fps) << " frames per second";
    if (fps < r.settings.fps) {
      o << " (" << fmt("%.2g", r.settings.fps / fps) << " times slower than the scene's "
        << fmt("%g", r.settings.fps) << ", so that the loop lasts " << fmt("%.2g", frames / fps)
        << " s)";
    }
    o << ".</figcaption></figure>\n";
  }
  o << "</section>\n";
  return o.str();
}

}  // namespace

std::string report_html(const StudyResults& r) {
  const StudySettings& s = r.settings;
  std::ostringstream o;
  o << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>sunglint study</title>\n<link rel=\"stylesheet\" href=\"report.css\">\n"
    << "</head><body>\n<header><h1>sunglint study</h1>\n";
  o << "<p>" << s.width << "&times;" << s.height << " pixels, frames " << s.first_frame << "&ndash;"
    << s.last_frame << ", reference " << code(s.reference) << ". Methods:";
  for (const auto& m : s.methods)
    o << " " << code(m);
  o << ".</p>\n";
  if (!s.command.empty()) o << "<p class=\"cmd\">" << code(s.command) << "</p>\n";
  o << "<nav><a href=\"#summary\">summary</a> ";
  for (const auto& sc : r.scenes)
    o << "<a href=\"#scene-" << file_slug(sc.name) << "\">" << html_escape(sc.name) << "</a> ";
  o << "<a href=\"#notes\">definitions</a></nav></header>\n<main>\n";
  o << summary_section(r);

  if (studies_a_paper_scene(r)) {
    o << "<section id=\"table1\"><h2>Table 1 of Podee et al. (2021) beside ours</h2>\n"
      << "<p>RMSE, with the ratio to No AA in brackets. The paper measures pictures after "
         "glare and tone mapping against its reference; we measure linear pixel values against "
         "ours. Compare the ratios, not the absolute values.</p>\n"
      << paper_table(r);
    for (const std::string& v : paper_table_verdict(r, code))
      o << "<p class=\"verdict\">" << v << "</p>\n";
    o << "</section>\n";
  }

  o << "<section id=\"charts\"><h2>Error per method and scene</h2>\n<div class=\"charts\">"
    << "<div class=\"chart\"><canvas id=\"chart-rmse\"></canvas></div>"
    << "<div class=\"chart\"><canvas id=\"chart-temporal\"></canvas></div>"
    << "<div class=\"chart\"><canvas id=\"chart-nearfar\"></canvas></div>"
    << "<div class=\"chart\"><canvas id=\"chart-time\"></canvas></div></div>\n"
    << "<p>Every axis of values is logarithmic: the scenes' errors and times span orders "
       "of magnitude. The quality&ndash;cost curve of supersampling (RMSE against time per "
       "frame) is drawn in each scene's section, with each method as a point.</p></section>\n";

  for (const auto& sc : r.scenes)
    o << scene_section(sc, r);

  o << "<section id=\"notes\"><h2>Definitions</h2><ul>\n"
    << "<li>Metrics are computed on linear pixel values, never on the pictures: RMSE over "
       "all pixels of all frames; PSNR = 20 log<sub>10</sub>(1 / RMSE); temporal error = RMS "
       "over pixels and frame pairs of (I<sub>f</sub> &minus; I<sub>f&minus;1</sub>) &minus; "
       "(R<sub>f</sub> &minus; R<sub>f&minus;1</sub>); flicker = mean |I<sub>f</sub> &minus; "
       "I<sub>f&minus;1</sub>|.</li>\n"
    << "<li>Colour scenes: every figure is taken over the three channels together (RMSE "
       "over 3 W H values per frame); the per-channel table gives each channel alone.</li>\n"
    << "<li>Near and far: the pixels whose centre ray meets the water, sorted by the "
       "distance from the camera to that point; the nearer half and the farther half.</li>\n"
    << "<li>Pictures and videos: value &times; 2<sup>" << fmt("%g", s.exposure)
    << "</sup>, glare (a sum of Gaussian blurs and a six-point star of the part above 1), "
       "ACES filmic curve (Narkowicz 2016), sRGB; identical for every method.</li>\n"
    << "<li>Time per frame: wall time of one frame on all threads of this machine; frames "
       "taken from the cache keep the time measured when they were rendered.</li>\n"
    << "<li>Charts: <a href=\"chart.js-LICENSE.md\">Chart.js</a> (MIT).</li></ul></section>\n";
  o << "</main>\n";

  std::string data = results_to_json(r);
  for (size_t p = 0; (p = data.find("</", p)) != std::string::npos; p += 3)
    data.replace(p, 2, "<\\/");  // never close the script element early
  o << "<script id=\"sg-results\" type=\"application/json\">\n"
    << data << "</script>\n<script src=\"chart.umd.min.js\"></script>\n"
    << "<script src=\"report.js\"></script>\n</body></html>\n";
  return o.str();
}

void write_report_html(const StudyResults& r, const std::string& out_dir) {
  const fs::path d(out_dir);
  for (const EmbeddedFile& f : report_assets())
    write_file_atomic((d / std::string(f.name)).string(), f.bytes);
  write_file_atomic((d / "index.html").string(), report_html(r));
}

}  // namespace sg
