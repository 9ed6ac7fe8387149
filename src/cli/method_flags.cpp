#include "cli/method_flags.h"

#include <sstream>
#include <vector>

#include "base/error.h"
#include "methods/options.h"
#include "methods/method.h"

namespace sg {

void MethodFlags::finish(const std::string& context) {
  options.samples = parse_sample_counts(samples, context + "--samples");
  StaaOptions& s = options.staa;
  s.ndf = ndf == "uniform" ? NdfMode::uniform : NdfMode::per_pixel;
  s.ndf_mean_shift = ndf_mean == "shift";
  s.fallback = fallback == "riemann" ? FallbackMode::riemann : FallbackMode::quadrature;
  s.nyquist_max_axis = nyquist == "max";
  s.fallback_along_path = fallback_time == "path";
  if (!(s.alias_start >= 0 && s.alias_end > s.alias_start)) {
    throw Error(context + "--alias-start, --alias-end: need 0 <= start < end (got " +
                std::to_string(s.alias_start) + ", " + std::to_string(s.alias_end) + ")");
  }
}

void add_method_flags(CLI::App& app, MethodFlags& f) {
  app.add_option("--samples", f.samples, "Samples SxSxT for reference and supersample")
      ->capture_default_str();
  app.add_option("--seed", f.options.seed, "Seed of the sampling streams")->capture_default_str();
  StaaOptions& s = f.options.staa;
  app.add_option("--segments", s.segments,
                 "staa, staa-temporal: sub-arcs of the shutter interval (Sec. 3.5)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  app.add_option("--ndf", f.ndf, "staa: NDF of the aliasing waves: uniform (Eq. 3) or per-pixel "
                                 "(Eqs. 4-7)")
      ->capture_default_str()
      ->check(CLI::IsMember({"uniform", "per-pixel"}));
  app.add_option("--ndf-mean", f.ndf_mean,
                 "staa, per-pixel NDF: the aliasing waves' mean slope shifts the NDF centre "
                 "(shift) or not (none)")
      ->capture_default_str()
      ->check(CLI::IsMember({"shift", "none"}));
  app.add_option("--kernels", s.kernels,
                 "staa: circular Gaussians approximating the RDF: 1 (equal-area circle, Sec. "
                 "3.5), 3, 5 or 9 (Sec. 3.6)")
      ->capture_default_str()
      ->check(CLI::IsMember({1, 3, 5, 9}));
  app.add_option("--elongation-threshold", s.elongation_threshold,
                 "staa: RDF axis ratio past which the fallback renders (0: the kernel count, "
                 "as the paper)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--fallback", f.fallback,
                 "staa: fallback past the elongation threshold: quadrature (accurate) or "
                 "riemann (the paper's Riemann sum)")
      ->capture_default_str()
      ->check(CLI::IsMember({"quadrature", "riemann"}));
  app.add_option("--fallback-time", f.fallback_time,
                 "staa: the fallback averaged along the reflection path (path) or at the display "
                 "time only (current, the paper)")
      ->capture_default_str()
      ->check(CLI::IsMember({"path", "current"}));
  app.add_option("--riemann-cells", s.riemann_cells, "staa: cells across the disk for riemann")
      ->capture_default_str()
      ->check(CLI::Range(2, 1024));
  app.add_option("--alias-start", s.alias_start,
                 "staa: projected frequency (cycles/pixel) where aliasing begins (Eq. 20)")
      ->capture_default_str();
  app.add_option("--alias-end", s.alias_end,
                 "staa: projected frequency (cycles/pixel) where a wave fully aliases (Eq. 20)")
      ->capture_default_str();
  app.add_option("--nyquist", f.nyquist,
                 "staa: projected frequency as the larger axis frequency (max) or the norm")
      ->capture_default_str()
      ->check(CLI::IsMember({"max", "norm"}));
}

MethodVariant parse_method_variant(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
    words.push_back(w);
  if (words.empty()) throw Error("--methods: empty method variant");
  MethodVariant v;
  v.label = text;
  v.name = words[0];
  CLI::App app{"method variant"};
  MethodFlags flags;
  add_method_flags(app, flags);
  std::vector<std::string> args(words.rbegin(), words.rend() - 1);  // CLI11 wants them reversed
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw Error("--methods: '" + text + "': " + e.what());
  }
  flags.finish("--methods: '" + text + "': ");
  v.options = flags.options;
  make_method(v.name, v.options);  // validates the name
  return v;
}

}  // namespace sg
