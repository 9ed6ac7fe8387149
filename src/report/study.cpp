#include "report/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "base/atomic_file.h"
#include "base/error.h"
#include "engine/render.h"
#include "image/display.h"
#include "methods/reference.h"
#include "metrics/metrics.h"
#include "report/cache.h"
#include "report/figures.h"
#include "report/html.h"
#include "report/paper.h"
#include "report/regions.h"
#include "report/video.h"

namespace sg {
namespace fs = std::filesystem;

std::string default_equal_cost_target(const std::vector<StudyVariant>& methods) {
  auto first = [&](auto pred) -> std::string {
    for (const auto& m : methods) {
      if (pred(m)) return canonical_label(m.label);
    }
    return "";
  };
  auto estimator = [](const StudyVariant& m) {
    return m.name == "reference" || m.name == "supersample";
  };
  std::string t = first([](const StudyVariant& m) { return m.name == "staa"; });
  if (t.empty())
    t = first([&](const StudyVariant& m) { return !estimator(m) && m.name != "point"; });
  if (t.empty()) t = first([&](const StudyVariant& m) { return !estimator(m); });
  return t;
}

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::unique_ptr<Method> build(const StudyVariant& v) {
  return v.make ? v.make() : make_method(v.name, v.options);
}

// Samples per pixel of the supersampling estimators; 0 for other methods. The reference's
// are those of its busy pixels: every batch's strata times their samples (its own default
// when --samples is not given; the pilot's quiet pixels take fewer).
double samples_per_pixel(const StudyVariant& v) {
  if (v.name == "reference") {
    const ReferenceSettings rs = reference_settings(v.options);
    return double(rs.samples.total()) * rs.batches;
  }
  if (v.name == "supersample") return double(v.options.samples.total());
  return 0.0;
}

// Relative cost of one frame, for the progress bar only: the samples per pixel of the
// supersampling estimators, and a few for every other method (a few times `point`).
double cost_weight(const StudyVariant& v) {
  const double spp = samples_per_pixel(v);
  return spp > 0 ? spp : 2.0;
}

struct Sequence {
  std::vector<Image> frames;
  // A method that measures its own noise (reference): each frame's per-pixel variance of
  // its estimate, cached beside the frame (variance_key); empty for other methods.
  std::vector<Image> variance;
  double ms_per_frame = 0;
  int rendered = 0, cached = 0;
  bool stateful = false;
};

// Distinct file names for labels (file_slug, then -2, -3 ... on a collision).
std::vector<std::string> unique_slugs(const std::vector<std::string>& labels) {
  std::vector<std::string> out;
  std::set<std::string> used;
  for (const auto& l : labels) {
    std::string s = file_slug(l), t = s;
    for (int k = 2; used.count(t); ++k)
      t = s + "-" + std::to_string(k);
    used.insert(t);
    out.push_back(t);
  }
  return out;
}

class Study {
 public:
  Study(const StudyConfig& c, const StudyProgress& p) : c_(c), progress_(p) {}

  StudyResults run();

 private:
  // All variants of a scene, each label once: reference, methods, budgets.
  std::vector<const StudyVariant*> variants() const {
    std::vector<const StudyVariant*> v{&c_.reference};
    for (const auto& m : c_.methods)
      v.push_back(&m);
    for (const auto& b : c_.budgets)
      v.push_back(&b);
    std::vector<const StudyVariant*> out;
    std::set<std::string> seen;
    for (const auto* x : v) {
      if (seen.insert(canonical_label(x->label)).second) out.push_back(x);
    }
    return out;
  }
  std::vector<std::string> keys(const Scene& s, const std::string& label, bool stateful) const {
    std::vector<std::string> k;
    for (int f = c_.first_frame; f <= c_.last_frame; ++f)
      k.push_back(frame_key(s, label, f, stateful ? c_.first_frame : -1));
    return k;
  }
  // Frames to render for a variant (for the progress total).
  int frames_to_render(const Scene& s, const StudyVariant& v) const {
    const std::string label = canonical_label(v.label);
    const bool stateful = build(v)->stateful();
    int missing = 0;
    for (const auto& k : keys(s, label, stateful))
      missing += cache_->has(label, k) ? 0 : 1;
    return stateful && missing > 0 ? c_.last_frame - c_.first_frame + 1 : missing;
  }
  void report(double fraction, const std::string& what) {
    if (progress_) progress_(std::clamp(fraction, 0.0, 1.0), what);
  }
  Sequence obtain(const SceneModel& model, const StudyVariant& v, const std::string& what);
  VariantResult measure(const StudyVariant& v, const Sequence& s, const Sequence& ref,
                        const WaterRegions& w) const;
  SceneResult run_scene(const StudyScene& sc, const std::string& scene_slug);

  const StudyConfig& c_;
  const StudyProgress& progress_;
  std::optional<FrameCache> cache_;  // created once the configuration is checked
  double total_weight_ = 0, done_weight_ = 0;
};

Sequence Study::obtain(const SceneModel& model, const StudyVariant& v, const std::string& what) {
  const std::string label = canonical_label(v.label);
  std::unique_ptr<Method> method = build(v);
  Sequence s;
  s.stateful = method->stateful();
  const bool noise = method->pixel_variance() != nullptr;
  const int a = c_.first_frame, n = c_.last_frame - c_.first_frame + 1;
  const std::vector<std::string> k = keys(model.scene, label, s.stateful);
  s.frames.resize(n);
  if (noise) s.variance.resize(n);
  std::vector<double> ms(n, 0.0);
  std::vector<bool> have(n, false);
  for (int q = 0; q < n; ++q) {
    auto f = cache_->load(label, k[q]);
    if (f && f->image.width == model.width() && f->image.height == model.height() &&
        f->image.channels == (model.scene.grey() ? 1 : 3)) {
      s.frames[q] = std::move(f->image);
      ms[q] = f->ms;
      have[q] = true;
    }
    if (have[q] && noise) {  // a frame without its variance is rendered again
      auto v = cache_->load(label, variance_key(k[q]));
      have[q] = v && v->image.same_shape(s.frames[q]);
      if (have[q]) s.variance[q] = std::move(v->image);
    }
  }
  const int missing = static_cast<int>(std::count(have.begin(), have.end(), false));
  const double weight = cost_weight(v);
  RenderSettings rs;
  rs.threads = c_.threads;
  rs.seed = v.options.seed;
  rs.progress = [&](long done, long total) {
    report((done_weight_ + weight * double(done) / double(total)) / total_weight_, what);
  };
  auto keep = [&](int f, const Image& img, double t) {
    const int q = f - a;
    if (q < 0 || q >= n) return;  // frames before the range (warm-up) are not kept
    if (noise) {                  // before the frame, whose sidecar vouches for both
      s.variance[q] = *method->pixel_variance();
      cache_->store(label, variance_key(k[q]), s.variance[q], t);
    }
    cache_->store(label, k[q], img, t);
    s.frames[q] = img;
    ms[q] = t;
    ++s.rendered;
    done_weight_ += weight;
  };
  if (s.stateful && missing > 0) {  // history: the whole range again, in order
    Clock::time_point t0 = Clock::now();
    render_frames(model, *method, c_.first_frame, c_.last_frame, rs, [&](int f, const Image& img) {
      const double t = ms_since(t0);
      keep(f, img, t);
      t0 = Clock::now();
    });
  } else {
    for (int q = 0; q < n; ++q) {
      if (have[q]) continue;
      const Clock::time_point t0 = Clock::now();
      Image img = render_frame(model, *method, a + q, rs);
      keep(a + q, img, ms_since(t0));
    }
  }
  s.cached = n - s.rendered;
  double sum = 0;
  for (double t : ms)
    sum += t;
  s.ms_per_frame = sum / n;
  return s;
}

VariantResult Study::measure(const StudyVariant& v, const Sequence& s, const Sequence& reference,
                             const WaterRegions& w) const {
  const std::vector<Image>& ref = reference.frames;
  VariantResult r;
  r.label = canonical_label(v.label);
  r.name = v.name;
  r.stateful = s.stateful;
  r.spp = samples_per_pixel(v);
  r.ms_per_frame = s.ms_per_frame;
  r.frames_rendered = s.rendered;
  r.frames_cached = s.cached;
  const std::vector<unsigned char>* masks[4] = {nullptr, &w.water, &w.near, &w.far};
  for (int k = 0; k < 4; ++k) {
    const SequenceMetrics m = compare_sequences(s.frames, ref, 1.0, masks[k]);
    RegionMetrics& o = r.regions[k];
    o.rmse = m.rmse;
    o.psnr = psnr_from_rmse(m.rmse, 1.0);
    o.temporal_error = m.temporal_error;
    o.flicker = m.flicker_a;
    o.flicker_reference = m.flicker_b;
    o.pixels = m.frames.front().pixels;
    if (!reference.variance.empty()) {
      o.reference_se = sequence_standard_error(reference.variance, masks[k]);
      o.rmse_corrected = noise_corrected_rmse(o.rmse, o.reference_se);
    } else {
      o.reference_se = std::numeric_limits<double>::quiet_NaN();
      o.rmse_corrected = o.rmse;
    }
    if (m.channels.size() == 3) {
      for (const SequenceChannelMetrics& c : m.channels)
        o.channels.push_back({c.rmse, c.temporal_error, c.flicker_a});
    }
  }
  return r;
}

// The pixel where `a` has its largest temporal error against `ref` (summed over frame pairs
// and channels), among the pixels of `mask`; {-1, -1} with fewer than two frames.
std::pair<int, int> largest_temporal_error(const std::vector<Image>& a,
                                           const std::vector<Image>& ref,
                                           const std::vector<unsigned char>& mask) {
  if (a.size() < 2 || ref.size() != a.size()) return {-1, -1};
  const Image& first = a.front();
  std::vector<double> te(first.pixels(), 0.0);
  const int n = std::max(first.channels, ref.front().channels);
  for (size_t f = 1; f < a.size(); ++f) {
    for (size_t k = 0; k < te.size(); ++k) {
      for (int c = 0; c < n; ++c) {
        const double da = double(channel_value(a[f], k, c)) - channel_value(a[f - 1], k, c);
        const double dr = double(channel_value(ref[f], k, c)) - channel_value(ref[f - 1], k, c);
        te[k] += (da - dr) * (da - dr);
      }
    }
  }
  size_t best = 0;
  double best_te = -1;
  for (size_t k = 0; k < te.size(); ++k) {
    if (mask[k] && te[k] > best_te) {
      best = k;
      best_te = te[k];
    }
  }
  return {static_cast<int>(best % first.width), static_cast<int>(best / first.width)};
}

// The value of pixel (x, y), the mean over its channels, in each frame.
std::vector<double> pixel_trace(const std::vector<Image>& frames, int x, int y) {
  std::vector<double> t;
  for (const Image& f : frames) {
    double v = 0;
    for (int c = 0; c < f.channels; ++c)
      v += f.at(x, y, c);
    t.push_back(v / f.channels);
  }
  return t;
}

SceneResult Study::run_scene(const StudyScene& sc, const std::string& scene_slug) {
  const Scene& scene = sc.scene;
  const SceneModel model(scene);
  SceneResult r;
  r.name = scene.name;
  r.file = sc.file;
  r.shown_frame = c_.last_frame;
  const WaterRegions w = water_regions(model, frame_time(scene, c_.first_frame).end);
  r.water_pixels = w.water_pixels;
  r.near_pixels = w.near_pixels;
  r.far_pixels = w.far_pixels;
  r.split_distance = w.split_distance;

  const std::string tag = scene.name + ": ";
  const Sequence ref = obtain(model, c_.reference, tag + canonical_label(c_.reference.label));
  r.reference = measure(c_.reference, ref, ref, w);

  // Methods: metrics, and the display frames of every variant for pictures and videos.
  std::vector<Sequence> seqs;
  for (const auto& m : c_.methods) {
    seqs.push_back(obtain(model, m, tag + canonical_label(m.label)));
    r.methods.push_back(measure(m, seqs.back(), ref, w));
  }
  for (const auto& b : c_.budgets) {
    const Sequence s = obtain(model, b, tag + canonical_label(b.label));
    r.budgets.push_back(measure(b, s, ref, w));
  }
  std::stable_sort(r.budgets.begin(), r.budgets.end(),
                   [](const VariantResult& x, const VariantResult& y) { return x.spp < y.spp; });

  if (!c_.equal_cost_target.empty()) {
    for (const auto& m : r.methods) {
      if (m.label != c_.equal_cost_target) continue;
      EqualCost e;
      e.target = m.label;
      e.target_ms = m.ms_per_frame;
      e.target_rmse = m.at(Region::image).rmse;
      std::vector<CurvePoint> curve;
      for (const auto& b : r.budgets) {
        const CurvePoint p{b.spp, b.ms_per_frame, b.at(Region::image).rmse};
        if (p.spp > 0 && p.ms > 0 && p.rmse > 0) curve.push_back(p);
      }
      e.cost = same_cost(curve, e.target_ms);
      e.rmse = same_rmse(curve, e.target_rmse);
      r.equal_cost = e;
    }
  }

  // The flicker plot: the pixel where point sampling (else the first method) has its
  // largest temporal error on the water, and every column's value there over time.
  r.channels = ref.frames.front().channels;
  if (!seqs.empty()) {
    size_t by = 0;
    for (size_t m = 0; m < c_.methods.size(); ++m) {
      if (c_.methods[m].name == "point") {
        by = m;
        break;
      }
    }
    const std::vector<unsigned char> everywhere(ref.frames.front().pixels(), 1);
    const auto [x, y] = largest_temporal_error(seqs[by].frames, ref.frames,
                                               w.water_pixels > 0 ? w.water : everywhere);
    if (x >= 0) {
      r.flicker_pixel = FlickerPixel{x, y, r.methods[by].label};
      r.reference.trace = pixel_trace(ref.frames, x, y);
      for (size_t m = 0; m < seqs.size(); ++m)
        r.methods[m].trace = pixel_trace(seqs[m].frames, x, y);
    }
  }

  if (!c_.pictures && !c_.video) return r;
  report(done_weight_ / total_weight_, tag + "pictures and video");
  const int W = scene.width, H = scene.height, n = static_cast<int>(ref.frames.size());
  const int z = std::max(1, c_.zoom);
  const int cw = std::max(1, W / z), ch = std::max(1, H / z);
  const Image& ref_shown = ref.frames.back();
  r.far_crop = best_crop(ref_shown, w.far, cw, ch);
  r.near_crop = best_crop(ref_shown, w.near, cw, ch, &r.far_crop);
  const std::vector<unsigned char> all(ref_shown.pixels(), 1);
  const int C = ref_shown.channels;
  const std::vector<unsigned char>& error_mask = w.water_pixels > 0 ? w.water : all;
  for (const auto& s : seqs) {
    r.error_range =
        std::max(r.error_range, error_scale(s.frames.back(), ref_shown, error_mask, 0.98));
  }
  if (!(r.error_range > 0)) r.error_range = 1.0;

  // Columns: the reference, then each method.
  std::vector<const Sequence*> cols{&ref};
  std::vector<VariantResult*> results{&r.reference};
  std::vector<std::string> labels{r.reference.label};
  for (size_t m = 0; m < seqs.size(); ++m) {
    cols.push_back(&seqs[m]);
    results.push_back(&r.methods[m]);
    labels.push_back(r.methods[m].label);
  }
  const std::vector<std::string> slugs = unique_slugs(labels);
  const std::string img_dir = "img/" + scene_slug;
  fs::create_directories(fs::path(c_.out_dir) / img_dir);
  const uint8_t kBackground = 24, kNear[3] = {255, 160, 32}, kFar[3] = {64, 200, 255};
  std::vector<std::vector<Picture>> grid(5);
  std::vector<std::vector<Picture>> crops;  // per column: near and far at kCropScale:1
  // Display frames of every column: all frames for the video, the last for pictures.
  std::vector<std::vector<std::vector<uint8_t>>> shown(cols.size());
  for (size_t col = 0; col < cols.size(); ++col) {
    const auto& frames = cols[col]->frames;
    for (int f = c_.video ? 0 : n - 1; f < n; ++f)
      shown[col].push_back(display_srgb8(frames[f], c_.display));
    Picture pic = to_picture(W, H, C, shown[col].back());
    Picture marked = pic;
    if (col == 0) {
      draw_box(marked, r.near_crop, kNear);
      draw_box(marked, r.far_crop, kFar);
    }
    // The error map on linear values; the reference's column shows the colour scale.
    Picture err(W, H, kBackground);
    if (col == 0) {
      const Picture scale = colour_scale(W, std::max(1, H / 6));
      for (int j = 0; j < scale.height; ++j)
        std::copy(scale.at(0, j), scale.at(0, j) + 3 * W, err.at(0, (H - scale.height) / 2 + j));
    } else {
      err.rgb = difference_rgb8(cols[col]->frames.back(), ref_shown, r.error_range);
    }
    auto error_crop = [&](const CropBox& box) {
      return col == 0 ? err : zoomed_crop(err, box, z, W, H, kBackground);
    };
    grid[0].push_back(marked);
    grid[1].push_back(zoomed_crop(pic, r.near_crop, z, W, H, kBackground));
    grid[2].push_back(error_crop(r.near_crop));
    grid[3].push_back(zoomed_crop(pic, r.far_crop, z, W, H, kBackground));
    grid[4].push_back(error_crop(r.far_crop));
    crops.push_back(
        {enlarged_crop(pic, r.near_crop, kCropScale), enlarged_crop(pic, r.far_crop, kCropScale)});
    if (c_.pictures) {
      results[col]->picture = img_dir + "/" + slugs[col] + ".png";
      write_picture((fs::path(c_.out_dir) / results[col]->picture).string(), pic);
      results[col]->near_crop_picture = img_dir + "/" + slugs[col] + "-near.png";
      results[col]->far_crop_picture = img_dir + "/" + slugs[col] + "-far.png";
      write_picture((fs::path(c_.out_dir) / results[col]->near_crop_picture).string(),
                    crops.back()[0]);
      write_picture((fs::path(c_.out_dir) / results[col]->far_crop_picture).string(),
                    crops.back()[1]);
      if (col > 0) {
        results[col]->error_map = img_dir + "/" + slugs[col] + "-error.png";
        write_picture((fs::path(c_.out_dir) / results[col]->error_map).string(), err);
      }
    }
  }
  if (c_.pictures) {
    r.grid = "img/" + scene_slug + "-grid.png";
    write_picture((fs::path(c_.out_dir) / r.grid).string(), compose_grid(grid, 2, kBackground));
    r.crops = "img/" + scene_slug + "-crops.png";
    write_picture((fs::path(c_.out_dir) / r.crops).string(), compose_grid(crops, 2, kBackground));
  }
  if (c_.video) {
    // Two rows: the frames, and their near crops zoomed; columns as in the grid.
    const int gap = 2, VW = int(cols.size()) * W + (int(cols.size()) - 1) * gap, VH = 2 * H + gap;
    std::vector<std::vector<uint8_t>> frames(
        n, std::vector<uint8_t>(size_t(VW) * VH * C, kBackground));
    for (int f = 0; f < n; ++f) {
      for (size_t col = 0; col < cols.size(); ++col) {
        const Picture pic = to_picture(W, H, C, shown[col][f]);
        const Picture crop = zoomed_crop(pic, r.near_crop, z, W, H, kBackground);
        const int x0 = int(col) * (W + gap);
        for (int j = 0; j < H; ++j) {
          for (int i = 0; i < W; ++i) {
            for (int c = 0; c < C; ++c) {
              frames[f][(size_t(j) * VW + x0 + i) * C + c] =
                  shown[col][f][(size_t(j) * W + i) * C + c];
              frames[f][(size_t(H + gap + j) * VW + x0 + i) * C + c] = crop.at(i, j)[c];
            }
          }
        }
      }
    }
    fs::create_directories(fs::path(c_.out_dir) / "video");
    r.video = "video/" + scene_slug + ".mp4";
    const std::string video = (fs::path(c_.out_dir) / r.video).string();
    // Played slower than the scene when its frames would last under 3 s (report/video.h).
    const double fps = playback_fps(scene.animation.fps, n);
    if (C == 1) {
      encode_h264(video, VW, VH, fps, frames);
    } else {
      encode_h264_rgb(video, VW, VH, fps, frames);
    }
  }
  return r;
}

StudyResults Study::run() {
  if (c_.scenes.empty()) throw Error("compare: give at least one scene file");
  if (c_.methods.empty()) throw Error("--method: give at least one method variant");
  if (c_.out_dir.empty()) throw Error("--out: give the study's folder");
  if (c_.first_frame < 0 || c_.last_frame < c_.first_frame) {
    throw Error("--frames: expected a frame range A-B with 0 <= A <= B");
  }
  std::vector<std::string> method_labels;
  for (const auto& m : c_.methods)
    method_labels.push_back(canonical_label(m.label));
  for (size_t k = 0; k < method_labels.size(); ++k) {
    if (std::count(method_labels.begin(), method_labels.end(), method_labels[k]) > 1) {
      throw Error("--method: '" + method_labels[k] + "' is given twice");
    }
  }
  if (!c_.equal_cost_target.empty() && std::find(method_labels.begin(), method_labels.end(),
                                                 c_.equal_cost_target) == method_labels.end()) {
    throw Error("--equal-cost-target: '" + c_.equal_cost_target +
                "' is not one of the methods (add it with --method)");
  }
  const auto paper_rows = match_paper_rows(method_labels, c_.paper_rows);
  for (const auto& s : c_.scenes) {
    if (c_.last_frame >= s.scene.animation.frames) {
      throw Error("--frames: frame " + std::to_string(c_.last_frame) +
                  " is outside the animation [0, " + std::to_string(s.scene.animation.frames - 1) +
                  "] of " + s.file);
    }
  }
  std::error_code ec;
  fs::create_directories(c_.out_dir, ec);
  if (!fs::is_directory(c_.out_dir)) throw Error("--out: cannot create '" + c_.out_dir + "'");
  cache_.emplace(c_.cache_dir.empty() ? (fs::path(c_.out_dir) / "cache").string() : c_.cache_dir);

  // Plan: the work still to do, for the progress bar.
  for (const auto& s : c_.scenes) {
    for (const StudyVariant* v : variants())
      total_weight_ += frames_to_render(s.scene, *v) * cost_weight(*v);
  }
  total_weight_ = std::max(total_weight_, 1e-9);

  StudyResults res;
  StudySettings& st = res.settings;
  st.width = c_.scenes.front().scene.width;
  st.height = c_.scenes.front().scene.height;
  st.first_frame = c_.first_frame;
  st.last_frame = c_.last_frame;
  st.fps = c_.scenes.front().scene.animation.fps;
  st.reference = canonical_label(c_.reference.label);
  st.methods = method_labels;
  for (const auto& b : c_.budgets)
    st.budgets.push_back(canonical_label(b.label));
  st.equal_cost_target = c_.equal_cost_target;
  st.exposure = c_.display.exposure;
  st.paper_rows = paper_rows;
  st.command = c_.command;

  std::vector<std::string> scene_names;
  for (const auto& s : c_.scenes)
    scene_names.push_back(s.scene.name);
  const std::vector<std::string> scene_slugs = unique_slugs(scene_names);
  for (size_t k = 0; k < c_.scenes.size(); ++k)
    res.scenes.push_back(run_scene(c_.scenes[k], scene_slugs[k]));
  report(1.0, "writing the report");
  write_study_outputs(res, c_.out_dir, c_.html);
  return res;
}

}  // namespace

StudyResults run_study(const StudyConfig& config, const StudyProgress& progress) {
  Study s(config, progress);
  return s.run();
}

void write_study_outputs(const StudyResults& r, const std::string& out_dir, bool html) {
  const fs::path d(out_dir);
  write_file_atomic((d / "results.json").string(), results_to_json(r));
  write_file_atomic((d / "results.csv").string(), results_to_csv(r));
  write_file_atomic((d / "results.md").string(), "# sunglint study\n\n" + results_to_markdown(r));
  if (html) write_report_html(r, out_dir);
}

}  // namespace sg
