#include "report/study.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <thread>
#include <tuple>

#include "base/atomic_file.h"
#include "base/error.h"
#include "engine/render.h"
#include "gl_engine/engines.h"
#include "image/display.h"
#include "methods/reference.h"
#include "metrics/metrics.h"
#include "report/cache.h"
#include "report/figures.h"
#include "report/html.h"
#include "report/paper.h"
#include "report/pixel_classes.h"
#include "report/plan.h"
#include "report/regions.h"
#include "report/video.h"
#include "scene/camera_path.h"
#include "shading/kernel_frame.h"

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

// The variant's method; for a reference, the one that renders batch `batch` alone (-1: all).
std::unique_ptr<Method> build(const StudyVariant& v, int batch = -1) {
  if (v.make) return v.make();
  if (batch < 0) return make_method_on(v.engine, v.name, v.options);
  MethodOptions o = v.options;
  o.only_batch = batch;
  return make_method_on(v.engine, v.name, o);
}

// The reference's batches (each a unit of the study); 0 for other variants.
int batch_count(const StudyVariant& v) {
  return v.name == "reference" && !v.make ? reference_settings(v.options).batches : 0;
}

// Wall seconds of the report's part of a scene (pictures, videos), for the time left: a
// cost per pixel of each frame of each column, measured on the 2-core development machine
// (docs/cluster.md), and a floor for the files.
double report_seconds(const StudyConfig& c, const Scene& s) {
  const double columns = 1.0 + double(c.methods.size());
  const double pixels = double(s.width) * s.height * (c.last_frame - c.first_frame + 1);
  double per_pixel = 0;
  if (c.pictures) per_pixel += 0.05e-6;
  if (c.video) per_pixel += 0.6e-6;
  return 0.2 + columns * pixels * per_pixel;
}

class Study {
 public:
  Study(const StudyConfig& c, const StudyProgress& p) : c_(c), progress_(p) {}

  // Checks the configuration (throws sg::Error naming the option), makes the cache.
  void check();
  std::vector<StudyUnit> units(bool missing_only) const;
  double pilot(std::vector<StudyUnit>& units);
  int render(const std::vector<StudyUnit>& units,
             const std::function<void(size_t, double)>& on_unit = {});
  // Local run: pilot, render and merge scene by scene. merge_only: from the cache alone.
  StudyResults run(bool merge_only);

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
  const StudyVariant& variant(const std::string& label) const {
    for (const StudyVariant* v : variants()) {
      if (canonical_label(v->label) == label) return *v;
    }
    throw Error("no variant '" + label + "' in the study");
  }
  bool stateful(const StudyVariant& v) const {
    const std::string label = canonical_label(v.label);
    auto it = stateful_.find(label);
    if (it != stateful_.end()) return it->second;
    return stateful_[label] = build(v)->stateful();
  }
  std::string key(const Scene& s, const StudyVariant& v, int frame) const {
    return frame_key(s, canonical_label(v.label), frame, stateful(v) ? c_.first_frame : -1);
  }
  // The cache key of a unit's frame `frame` (its batch's for a reference batch).
  std::string unit_key(const StudyUnit& u, int frame) const {
    const Scene& s = c_.scenes[u.scene].scene;
    const std::string k = key(s, variant(u.variant), frame);
    return u.batch >= 0 ? reference_batch_key(k, u.batch) : k;
  }
  bool complete(const StudyUnit& u) const {
    for (int f = u.first; f <= u.last; ++f) {
      if (!cache_->has(u.variant, unit_key(u, f))) return false;
    }
    return true;
  }
  void report(double fraction, double left, const std::string& what) {
    // The share done never goes back (a new measure may change the estimate's scale).
    shown_ = std::max(shown_, std::clamp(fraction, 0.0, 1.0));
    if (progress_) progress_({shown_, left, what});
  }
  // With no estimate (a task of a plan), the share of the units rendered.
  void report_estimate(const std::string& what, double share = 0) {
    if (estimate_) {
      report(estimate_->fraction(), estimate_->seconds_left(), what);
    } else {
      report(share, -1, what);
    }
  }
  Sequence load(const SceneModel& model, const StudyVariant& v, int scene) const;
  VariantResult measure(const StudyVariant& v, const Sequence& s, const Sequence& ref,
                        const WaterRegions& w) const;
  // The error split by what the pixel sees: masks[c][f] the pixels of class c in frame f.
  std::vector<ClassFigures> measure_classes(
      const Sequence& s, const Sequence& ref,
      const std::vector<std::vector<std::vector<unsigned char>>>& masks) const;
  SceneResult run_scene(int scene, const std::string& scene_slug);

  const StudyConfig& c_;
  const StudyProgress& progress_;
  std::optional<FrameCache> cache_;  // created once the configuration is checked
  mutable std::map<std::string, bool> stateful_;
  double shown_ = 0;
  std::optional<TimeEstimate> estimate_;
  std::vector<std::string> method_labels_;
  std::vector<std::pair<std::string, std::string>> paper_rows_;
  // Frames rendered in this run, per scene and variant label (a reference's frame when any
  // of its batches was); the first load of a label takes them (a budget that is also a
  // method was rendered once, then found in the cache).
  mutable std::map<std::pair<int, std::string>, std::set<int>> rendered_;
};

std::vector<StudyUnit> Study::units(bool missing_only) const {
  std::vector<StudyUnit> out;
  for (size_t s = 0; s < c_.scenes.size(); ++s) {
    const Scene& scene = c_.scenes[s].scene;
    for (const StudyVariant* v : variants()) {
      const std::string label = canonical_label(v->label);
      StudyUnit u;
      u.scene = static_cast<int>(s);
      u.variant = label;
      auto add = [&](int first, int last, int batch) {
        u.first = first;
        u.last = last;
        u.batch = batch;
        u.id = scene.name + ": " + label +
               (first == last ? ", frame " + std::to_string(first)
                              : ", frames " + std::to_string(first) + "-" + std::to_string(last) +
                                    " (stateful)");
        if (batch >= 0)
          u.id += ", batch " + std::to_string(batch + 1) + "/" + std::to_string(batch_count(*v));
        u.file = fs::path(cache_->path(label, unit_key(u, first))).filename().string();
        if (!missing_only || !complete(u)) out.push_back(u);
      };
      if (const int b = batch_count(*v); b > 0) {
        for (int f = c_.first_frame; f <= c_.last_frame; ++f) {
          for (int k = 0; k < b; ++k)
            add(f, f, k);
        }
      } else if (stateful(*v)) {
        add(c_.first_frame, c_.last_frame, -1);
      } else {
        for (int f = c_.first_frame; f <= c_.last_frame; ++f)
          add(f, f, -1);
      }
    }
  }
  return out;
}

// The tiles of a frame in an order that spreads any prefix over the image: k -> k p mod n,
// p the integer nearest n / golden ratio that is prime to n.
std::vector<int> spread_order(int n) {
  int p = std::max(1, static_cast<int>(std::lround(n * 0.6180339887)));
  while (std::gcd(p, n) != 1)
    ++p;
  std::vector<int> order(n);
  for (int k = 0; k < n; ++k)
    order[k] = static_cast<int>((long(k) * p) % n);
  return order;
}

double Study::pilot(std::vector<StudyUnit>& units) {
  const Clock::time_point t_pilot = Clock::now();
  // One thread: the estimate is in core-seconds (a task's cost on one core).
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::map<std::tuple<int, std::string>, double> frame_seconds;
  for (StudyUnit& u : units) {
    const auto at = std::make_tuple(u.scene, u.variant);
    auto it = frame_seconds.find(at);
    if (it == frame_seconds.end()) {
      const StudyVariant& v = variant(u.variant);
      const Scene& scene = c_.scenes[u.scene].scene;
      report(0, -1, "pilot: " + scene.name + ": " + u.variant);
      const SceneModel model(scene);
      std::unique_ptr<Method> method = build(v, u.batch >= 0 ? 0 : -1);
      Image img = Image::with_channels(model.width(), model.height(), scene.grey() ? 1 : 3);
      FrameContext ctx{model, frame_time(scene, u.first), v.options.seed};
      Clock::time_point t0 = Clock::now();
      method->begin_frame(ctx);
      const double setup = ms_since(t0) / 1000;
      constexpr int kTile = 16;
      constexpr double kTileBudget = 0.04;  // seconds of tiles per variant and scene
      const int tx = (model.width() + kTile - 1) / kTile, ty = (model.height() + kTile - 1) / kTile;
      double tiles = 0;
      long pixels = 0;
      for (int k : spread_order(tx * ty)) {
        const int x0 = (k % tx) * kTile, y0 = (k / tx) * kTile;
        const int x1 = std::min(model.width(), x0 + kTile),
                  y1 = std::min(model.height(), y0 + kTile);
        t0 = Clock::now();
        method->shade_tile(ctx, x0, y0, x1, y1, img);
        tiles += ms_since(t0) / 1000;
        pixels += long(x1 - x0) * (y1 - y0);
        if (tiles >= kTileBudget) break;
      }
      t0 = Clock::now();
      method->end_frame(ctx, img);
      const double finish = ms_since(t0) / 1000;
      const double all = double(model.width()) * model.height();
      it = frame_seconds.emplace(at, setup + finish + tiles * all / double(pixels)).first;
    }
    int frames = u.last - u.first + 1;
    if (u.last > u.first) frames += warmup_frame_count(*build(variant(u.variant)));
    u.seconds = it->second * frames;
  }
  return ms_since(t_pilot) / 1000;
}

int Study::render(const std::vector<StudyUnit>& units,
                  const std::function<void(size_t, double)>& on_unit) {
  int count = 0;
  std::unique_ptr<Method> method;  // reused by the units of one scene, variant and batch
  std::tuple<int, std::string, int> method_of{-1, "", -1};
  std::optional<SceneModel> model;
  int model_of = -1;
  for (size_t k = 0; k < units.size(); ++k) {
    const StudyUnit& u = units[k];
    if (complete(u)) continue;
    const StudyVariant& v = variant(u.variant);
    const Scene& scene = c_.scenes[u.scene].scene;
    if (model_of != u.scene) {
      model.emplace(scene);
      model_of = u.scene;
    }
    if (!method || method_of != std::make_tuple(u.scene, u.variant, u.batch) || u.last > u.first) {
      method = build(v, u.batch);
      method_of = {u.scene, u.variant, u.batch};
    }
    const std::string what = u.id;
    report_estimate(what, double(k) / double(units.size()));
    RenderSettings rs;
    rs.threads = c_.threads;
    rs.seed = v.options.seed;
    const long frames = u.last - u.first + 1 + (u.last > u.first ? warmup_frame_count(*method) : 0);
    long frames_done = 0;
    rs.progress = [&](long done, long total) {
      const double part = (double(frames_done) + double(done) / double(total)) / double(frames);
      if (estimate_) estimate_->partial(u.seconds * part);
      report_estimate(what, (double(k) + part) / double(units.size()));
      if (done == total) ++frames_done;
    };
    const Clock::time_point t_unit = Clock::now();
    auto keep = [&](int f, const Image& img, double ms) {
      if (f < u.first || f > u.last) return;  // frames before the range (warm-up)
      cache_->store(u.variant, unit_key(u, f), img, ms);
      rendered_[{u.scene, u.variant}].insert(f);
    };
    if (u.last > u.first) {  // a stateful variant's range, in order, its history whole
      Clock::time_point t0 = Clock::now();
      render_frames(*model, *method, u.first, u.last, rs, [&](int f, const Image& img) {
        keep(f, img, ms_since(t0));
        t0 = Clock::now();
      });
    } else {
      const Clock::time_point t0 = Clock::now();
      Image img = render_frame(*model, *method, u.first, rs);
      keep(u.first, img, ms_since(t0));
    }
    const double seconds = ms_since(t_unit) / 1000;
    if (estimate_) estimate_->done(u.seconds, seconds);
    ++count;
    if (on_unit) on_unit(k, seconds);
  }
  return count;
}

Sequence Study::load(const SceneModel& model, const StudyVariant& v, int scene) const {
  const std::string label = canonical_label(v.label);
  Sequence s;
  s.stateful = stateful(v);
  const int a = c_.first_frame, n = c_.last_frame - c_.first_frame + 1;
  const int channels = model.scene.grey() ? 1 : 3;
  const int batches = batch_count(v);
  auto get = [&](const std::string& k, int f) {
    auto c = cache_->load(label, k);
    if (!c) {
      throw Error(model.scene.name + ": " + label + ", frame " + std::to_string(f) +
                  ": not in the cache (" + cache_->path(label, k) + ")");
    }
    if (c->image.width != model.width() || c->image.height != model.height() ||
        c->image.channels != channels) {
      throw Error(cache_->path(label, k) + ": not the size of the study's frames; delete it");
    }
    return std::move(*c);
  };
  double sum_ms = 0;
  std::set<int> done;
  if (auto it = rendered_.find({scene, label}); it != rendered_.end()) {
    done = std::move(it->second);
    rendered_.erase(it);
  }
  for (int q = 0; q < n; ++q) {
    const std::string k = key(model.scene, v, a + q);
    if (batches == 0) {
      CachedFrame c = get(k, a + q);
      s.frames.push_back(std::move(c.image));
      sum_ms += c.ms;
    } else {
      // The reference: the mean of its batches, and their spread as the variance of that
      // mean per pixel and channel, sum (v_b - v)^2 / (B (B - 1)).
      std::vector<CachedFrame> b;
      for (int k2 = 0; k2 < batches; ++k2) {
        b.push_back(get(reference_batch_key(k, k2), a + q));
        sum_ms += b.back().ms;
      }
      Image mean = Image::with_channels(model.width(), model.height(), channels);
      Image var = Image::with_channels(model.width(), model.height(), channels);
      for (size_t i = 0; i < mean.data.size(); ++i) {
        double m = 0;
        for (const auto& x : b)
          m += x.image.data[i];
        m /= batches;
        double d = 0;
        for (const auto& x : b)
          d += (x.image.data[i] - m) * (x.image.data[i] - m);
        mean.data[i] = static_cast<float>(m);
        var.data[i] = static_cast<float>(d / (double(batches) * (batches - 1)));
      }
      s.frames.push_back(std::move(mean));
      s.variance.push_back(std::move(var));
    }
    s.rendered += done.count(a + q) ? 1 : 0;
  }
  s.cached = n - s.rendered;
  s.ms_per_frame = sum_ms / n;
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

std::vector<ClassFigures> Study::measure_classes(
    const Sequence& s, const Sequence& reference,
    const std::vector<std::vector<std::vector<unsigned char>>>& masks) const {
  std::vector<ClassFigures> out;
  const SequenceMetrics all = compare_sequences(s.frames, reference.frames);
  double total = 0;  // the squared error summed over the image's values and frames
  long image_pixels = 0;
  for (const ImageMetrics& m : all.frames) {
    total += m.rmse * m.rmse * m.pixels * double(m.channels.size());
    image_pixels += m.pixels;
  }
  for (size_t c = 0; c < masks.size(); ++c) {
    ClassFigures x;
    x.name = kPixelClassNames[c];
    std::vector<const std::vector<unsigned char>*> fm;
    for (const auto& m : masks[c])
      fm.push_back(&m);
    const SequenceMetrics m = compare_sequences(s.frames, reference.frames, 1.0, fm);
    double se2 = 0;
    long pixels = 0;
    for (const ImageMetrics& f : m.frames) {
      se2 += f.rmse * f.rmse * f.pixels * double(f.channels.size());
      pixels += f.pixels;
    }
    x.pixel_share = image_pixels > 0 ? double(pixels) / double(image_pixels) : 0;
    x.error_share = total > 0 ? se2 / total : 0;
    x.rmse = m.rmse;
    x.temporal_error = m.temporal_error;
    if (!reference.variance.empty() && pixels > 0) {
      x.reference_se = sequence_standard_error(reference.variance, fm);
      x.rmse_corrected = noise_corrected_rmse(x.rmse, x.reference_se);
      x.temporal_corrected = std::sqrt(
          std::max(0.0, x.temporal_error * x.temporal_error - 2 * x.reference_se * x.reference_se));
    } else {
      x.reference_se = std::numeric_limits<double>::quiet_NaN();
      x.rmse_corrected = x.rmse;
      x.temporal_corrected = x.temporal_error;
    }
    out.push_back(x);
  }
  return out;
}

SceneResult Study::run_scene(int scene_index, const std::string& scene_slug) {
  const StudyScene& sc = c_.scenes[scene_index];
  const Scene& scene = sc.scene;
  const SceneModel model(scene);
  SceneResult r;
  r.name = scene.name;
  r.file = sc.file;
  r.shown_frame = c_.last_frame;
  r.cascades = !scene.surface.cascades.empty();
  // The water regions of the first frame (of its camera, for a moving one); the camera's
  // motion over the frames studied (the report states it).
  const FrameTime first = frame_time(scene, c_.first_frame);
  const WaterRegions w = water_regions(frame_model(scene, first), first.end);
  if (scene.camera.moving()) {
    const double t_end = scene.frame_time(c_.last_frame);
    for (const CameraSegmentMotion& seg : camera_motion(scene.camera)) {
      if (seg.t1 <= first.start || seg.t0 >= t_end) continue;  // outside the frames
      r.moving_camera = r.moving_camera || seg.speed > 0 || seg.turn_rate_deg > 0;
      r.camera_speed = std::max(r.camera_speed, seg.speed);
      r.camera_turn_deg = std::max(r.camera_turn_deg, seg.turn_rate_deg);
    }
  }
  r.water_pixels = w.water_pixels;
  r.near_pixels = w.near_pixels;
  r.far_pixels = w.far_pixels;
  r.split_distance = w.split_distance;

  const std::string tag = scene.name + ": ";
  report_estimate(tag + "measures");
  const Sequence ref = load(model, c_.reference, scene_index);
  r.reference = measure(c_.reference, ref, ref, w);

  // Methods: metrics, and the display frames of every variant for pictures and videos.
  std::vector<Sequence> seqs;
  for (const auto& m : c_.methods) {
    seqs.push_back(load(model, m, scene_index));
    r.methods.push_back(measure(m, seqs.back(), ref, w));
  }
  for (const auto& b : c_.budgets) {
    const Sequence s = load(model, b, scene_index);
    r.budgets.push_back(measure(b, s, ref, w));
  }
  if (c_.split) {
    // What each pixel sees, frame by frame (the waves move; a moving camera too).
    report_estimate(tag + "what the pixels see");
    std::vector<std::vector<std::vector<unsigned char>>> masks(kPixelClasses);
    for (int f = c_.first_frame; f <= c_.last_frame; ++f) {
      const FrameTime ft = frame_time(scene, f);
      const PixelClasses pc =
          classify_pixels(frame_model(scene, ft), ft, kDefaultIntersectTolerance, c_.threads);
      for (int c = 0; c < kPixelClasses; ++c)
        masks[c].push_back(pc.mask(static_cast<PixelClass>(c)));
    }
    for (size_t m = 0; m < seqs.size(); ++m)
      r.methods[m].classes = measure_classes(seqs[m], ref, masks);
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
  report_estimate(tag + "pictures and video");
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

void Study::check() {
  if (cache_) return;
  if (c_.scenes.empty()) throw Error("compare: give at least one scene file");
  if (c_.methods.empty()) throw Error("--method: give at least one method variant");
  if (c_.out_dir.empty()) throw Error("--out: give the study's folder");
  if (c_.first_frame < 0 || c_.last_frame < c_.first_frame) {
    throw Error("--frames: expected a frame range A-B with 0 <= A <= B");
  }
  for (const auto& m : c_.methods)
    method_labels_.push_back(canonical_label(m.label));
  for (size_t k = 0; k < method_labels_.size(); ++k) {
    if (std::count(method_labels_.begin(), method_labels_.end(), method_labels_[k]) > 1) {
      throw Error("--method: '" + method_labels_[k] + "' is given twice");
    }
  }
  if (!c_.equal_cost_target.empty() && std::find(method_labels_.begin(), method_labels_.end(),
                                                 c_.equal_cost_target) == method_labels_.end()) {
    throw Error("--equal-cost-target: '" + c_.equal_cost_target +
                "' is not one of the methods (add it with --method)");
  }
  paper_rows_ = match_paper_rows(method_labels_, c_.paper_rows);
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
}

StudyResults Study::run(bool merge_only) {
  check();
  std::vector<StudyUnit> todo = units(true);
  if (merge_only && !todo.empty()) {
    std::string list;
    for (size_t k = 0; k < todo.size() && k < 5; ++k)
      list += "\n  " + todo[k].id + " (" + todo[k].file + ")";
    if (todo.size() > 5) list += "\n  ...";
    throw Error("--merge: " + std::to_string(todo.size()) +
                " of the study's units are not in the cache " + cache_->dir() + ":" + list +
                "\n(run the same command again without --merge to render them, or with --slurm to "
                "submit them)");
  }
  // The pilot, then the time left from its estimates and what is measured.
  double report_total = 0;
  std::vector<double> report_of;
  for (const auto& s : c_.scenes) {
    report_of.push_back(c_.pictures || c_.video ? report_seconds(c_, s.scene) : 0.2);
    report_total += report_of.back();
  }
  if (!todo.empty() && progress_) {
    pilot(todo);
    double total = 0;
    for (const auto& u : todo)
      total += u.seconds;
    const int threads =
        c_.threads > 0 ? c_.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    estimate_.emplace(total, 1.0 / threads, report_total);
  } else {
    estimate_.emplace(0, 1.0, report_total);
  }

  StudyResults res;
  StudySettings& st = res.settings;
  st.width = c_.scenes.front().scene.width;
  st.height = c_.scenes.front().scene.height;
  st.first_frame = c_.first_frame;
  st.last_frame = c_.last_frame;
  st.fps = c_.scenes.front().scene.animation.fps;
  st.reference = canonical_label(c_.reference.label);
  st.methods = method_labels_;
  for (const auto& b : c_.budgets)
    st.budgets.push_back(canonical_label(b.label));
  st.equal_cost_target = c_.equal_cost_target;
  st.exposure = c_.display.exposure;
  st.paper_rows = paper_rows_;
  st.command = c_.command;

  std::vector<std::string> scene_names;
  for (const auto& s : c_.scenes)
    scene_names.push_back(s.scene.name);
  const std::vector<std::string> scene_slugs = unique_slugs(scene_names);
  for (size_t k = 0; k < c_.scenes.size(); ++k) {
    std::vector<StudyUnit> mine;
    for (const auto& u : todo) {
      if (u.scene == int(k)) mine.push_back(u);
    }
    render(mine);
    res.scenes.push_back(run_scene(int(k), scene_slugs[k]));
    estimate_->fixed_done(report_of[k]);
  }
  report(1.0, 0, "writing the report");
  write_study_outputs(res, c_.out_dir, c_.html);
  return res;
}

}  // namespace

std::vector<StudyUnit> study_units(const StudyConfig& config, bool missing_only) {
  Study s(config, {});
  s.check();
  return s.units(missing_only);
}

double estimate_unit_costs(const StudyConfig& config, std::vector<StudyUnit>& units,
                           const StudyProgress& progress) {
  Study s(config, progress);
  s.check();
  return s.pilot(units);
}

int render_units(const StudyConfig& config, const std::vector<StudyUnit>& units,
                 const StudyProgress& progress,
                 const std::function<void(size_t unit, double seconds)>& on_unit) {
  Study s(config, progress);
  s.check();
  return s.render(units, on_unit);
}

StudyResults run_study(const StudyConfig& config, const StudyProgress& progress) {
  Study s(config, progress);
  return s.run(false);
}

StudyResults merge_study(const StudyConfig& config, const StudyProgress& progress) {
  Study s(config, progress);
  return s.run(true);
}

void write_study_outputs(const StudyResults& r, const std::string& out_dir, bool html) {
  const fs::path d(out_dir);
  write_file_atomic((d / "results.json").string(), results_to_json(r));
  write_file_atomic((d / "results.csv").string(), results_to_csv(r));
  write_file_atomic((d / "results.md").string(), "# sunglint study\n\n" + results_to_markdown(r));
  if (html) write_report_html(r, out_dir);
}

}  // namespace sg
