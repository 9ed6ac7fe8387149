// `sunglint diff A B [--frames A-B] [--out diff.png] [--json]`: the metrics of A against
// B (the reference), on linear values; for sequences also the temporal error and the
// flicker energy of each. Colour images are measured over all channels and per channel
// (R, G, B); a grey image against a colour one counts as three equal channels.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "base/error.h"
#include "base/output_path.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "image/display.h"
#include "image/image_io.h"
#include "image/sequence.h"
#include "metrics/metrics.h"

namespace sg {
namespace {

struct DiffArgs {
  std::string a, b, frames, out;
  double peak = 1.0, range = 0.0;
  bool json = false, mkdir = false;
};

constexpr const char* kChannelNames[3] = {"R", "G", "B"};
// Metrics of images holding NaN or infinities would be NaN or meaningless: refused.
const Image& finite_input(const Image& img, const std::string& path) {
  if (const size_t bad = count_nonfinite(img)) {
    throw Error(path + ": " + std::to_string(bad) + " of " + std::to_string(img.size()) +
                " pixels are not finite (NaN or infinite); metrics need finite values");
  }
  return img;
}

void check_diff_output(const std::string& path, bool mkdir) {
  if (check_output_file(path, mkdir, " (--mkdir creates it)")) {
    std::fprintf(stderr, "sunglint: created folder '%s' (--mkdir)\n",
                 std::filesystem::path(path).parent_path().c_str());
  }
}

nlohmann::json to_json(const ImageMetrics& m) {
  nlohmann::json j = {
      {"rmse", m.rmse},
      {"psnr", std::isfinite(m.psnr) ? nlohmann::json(m.psnr) : nlohmann::json("inf")},
      {"mean_a", m.mean_a},
      {"mean_b", m.mean_b},
      {"max_abs", m.max_abs},
      {"pixels", m.pixels}};
  if (m.channels.size() == 3) {  // colour: each channel's figures too
    j["channels"] = nlohmann::json::object();
    for (int c = 0; c < 3; ++c) {
      const ChannelMetrics& x = m.channels[c];
      j["channels"][kChannelNames[c]] = {
          {"rmse", x.rmse}, {"mean_a", x.mean_a}, {"mean_b", x.mean_b}, {"max_abs", x.max_abs}};
    }
  }
  return j;
}

// " (R x, G y, B z)" of three per-channel figures; "" for a grey comparison.
template <typename T, typename F>
std::string per_channel(const std::vector<T>& channels, F value) {
  if (channels.size() != 3) return "";
  char buf[128];
  std::snprintf(buf, sizeof buf, "  (R %.6g, G %.6g, B %.6g)", value(channels[0]),
                value(channels[1]), value(channels[2]));
  return buf;
}

void print_metrics(const ImageMetrics& m) {
  auto rmse = [](const ChannelMetrics& c) { return c.rmse; };
  auto max_abs = [](const ChannelMetrics& c) { return c.max_abs; };
  std::printf("rmse     %.6g%s\n", m.rmse, per_channel(m.channels, rmse).c_str());
  std::printf("psnr     %.2f dB\n", m.psnr);
  std::printf("mean     %.6g (A)  %.6g (B)\n", m.mean_a, m.mean_b);
  if (m.channels.size() == 3) {
    for (int c = 0; c < 3; ++c) {
      std::printf("mean %s   %.6g (A)  %.6g (B)\n", kChannelNames[c], m.channels[c].mean_a,
                  m.channels[c].mean_b);
    }
  }
  std::printf("max_abs  %.6g%s\n", m.max_abs, per_channel(m.channels, max_abs).c_str());
  std::printf("pixels   %ld\n", m.pixels);
}

void write_diff_picture(const std::string& path, const Image& a, const Image& b, double range,
                        double max_abs) {
  double r = range > 0 ? range : (max_abs > 0 ? max_abs : 1.0);
  write_png_rgb8(path, a.width, a.height, difference_rgb8(a, b, r));
}

void run_diff(const DiffArgs& d) {
  const bool seq = !d.frames.empty();
  FrameRange r;
  check_usage([&] {
    if (!(d.peak > 0)) throw Error("--peak: must be > 0");
    if (d.range < 0) throw Error("--range: must be >= 0");
    if (!d.out.empty()) {
      const std::string first =
          seq && is_frame_pattern(d.out) ? format_frame_path(d.out, 0, "--out") : d.out;
      if (image_format_of(first) != ImageFormat::png) {
        throw Error("--out: the difference picture is a .png file");
      }
    }
    if (!seq && (is_frame_pattern(d.a) || is_frame_pattern(d.b))) {
      throw Error("--frames: required when A or B is a sequence pattern such as frame_%04d.exr");
    }
    if (seq) {
      r = parse_frame_range(d.frames, "--frames");
      format_frame_path(d.a, r.first, "A");
      format_frame_path(d.b, r.first, "B");
    }
  });
  if (!seq) {
    if (!d.out.empty()) check_diff_output(d.out, d.mkdir);
    Image a = read_image(d.a), b = read_image(d.b);
    finite_input(a, d.a);
    finite_input(b, d.b);
    ImageMetrics m = compare_images(a, b, d.peak);
    if (!d.out.empty()) write_diff_picture(d.out, a, b, d.range, m.max_abs);
    if (d.json) {
      std::printf("%s\n", to_json(m).dump(2).c_str());
    } else {
      print_metrics(m);
    }
    return;
  }
  if (!d.out.empty()) {
    for (int f = r.first; f <= r.last; ++f) {
      if (!is_frame_pattern(d.out) && f != r.last) continue;
      check_diff_output(is_frame_pattern(d.out) ? format_frame_path(d.out, f, "--out") : d.out,
                        d.mkdir);
    }
  }
  std::vector<Image> a = read_sequence(d.a, r.first, r.last);
  std::vector<Image> b = read_sequence(d.b, r.first, r.last);
  for (int f = r.first; f <= r.last; ++f) {
    finite_input(a[f - r.first], format_frame_path(d.a, f, "A"));
    finite_input(b[f - r.first], format_frame_path(d.b, f, "B"));
  }
  SequenceMetrics s = compare_sequences(a, b, d.peak);
  if (!d.out.empty()) {
    // One picture per frame when --out is a pattern, else the last frame.
    for (int f = r.first; f <= r.last; ++f) {
      if (!is_frame_pattern(d.out) && f != r.last) continue;
      const auto& m = s.frames[f - r.first];
      std::string path = is_frame_pattern(d.out) ? format_frame_path(d.out, f, "--out") : d.out;
      write_diff_picture(path, a[f - r.first], b[f - r.first], d.range, m.max_abs);
    }
  }
  if (d.json) {
    nlohmann::json j = {{"frames", nlohmann::json::array()},
                        {"rmse", s.rmse},
                        {"psnr", psnr_from_rmse(s.rmse, d.peak)},
                        {"temporal_error", s.temporal_error},
                        {"flicker_a", s.flicker_a},
                        {"flicker_b", s.flicker_b}};
    if (s.channels.size() == 3) {
      j["channels"] = nlohmann::json::object();
      for (int c = 0; c < 3; ++c) {
        const SequenceChannelMetrics& x = s.channels[c];
        j["channels"][kChannelNames[c]] = {{"rmse", x.rmse},
                                           {"temporal_error", x.temporal_error},
                                           {"flicker_a", x.flicker_a},
                                           {"flicker_b", x.flicker_b}};
      }
    }
    for (size_t k = 0; k < s.frames.size(); ++k) {
      auto fj = to_json(s.frames[k]);
      fj["frame"] = r.first + static_cast<int>(k);
      j["frames"].push_back(fj);
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("frame  rmse        psnr(dB)  max_abs\n");
  for (size_t k = 0; k < s.frames.size(); ++k) {
    std::printf("%5d  %.6f  %8.2f  %.6f\n", r.first + static_cast<int>(k), s.frames[k].rmse,
                s.frames[k].psnr, s.frames[k].max_abs);
  }
  auto rmse = [](const SequenceChannelMetrics& c) { return c.rmse; };
  auto temporal = [](const SequenceChannelMetrics& c) { return c.temporal_error; };
  std::printf("rmse            %.6g (all frames)%s\n", s.rmse,
              per_channel(s.channels, rmse).c_str());
  std::printf("temporal_error  %.6g%s\n", s.temporal_error,
              per_channel(s.channels, temporal).c_str());
  std::printf("flicker         %.6g (A)  %.6g (B)\n", s.flicker_a, s.flicker_b);
}

}  // namespace

void add_diff_command(CLI::App& app) {
  auto d = std::make_shared<DiffArgs>();
  CLI::App* c = app.add_subcommand(
      "diff",
      "Compare image A with reference B (RMSE, PSNR, means, max |A-B|; for sequences "
      "also temporal error and flicker)");
  c->add_option("A", d->a, "Image (.exr, .pfm) or sequence pattern (frame_%04d.exr)")->required();
  c->add_option("B", d->b, "Reference image or sequence pattern")->required();
  c->add_option("--frames", d->frames, "Frame range A-B when A and B are sequence patterns");
  c->add_option("--out,-o", d->out,
                "Write a false-colour difference picture A-B (.png; blue: "
                "A darker, red: A brighter)");
  c->add_flag("--mkdir", d->mkdir, "Create the folder of --out when it is missing");
  c->add_option("--range", d->range,
                "Difference mapped to the ends of the colour map (default: "
                "max |A-B|)")
      ->check(finite_number());
  c->add_option("--peak", d->peak, "Peak value for PSNR")
      ->capture_default_str()
      ->check(finite_number());
  c->add_flag("--json", d->json, "Print JSON");
  c->callback([d] { run_diff(*d); });
}

}  // namespace sg
