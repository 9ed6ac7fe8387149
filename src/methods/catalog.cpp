// The list of methods and the factory behind `--method`.
#include "base/error.h"
#include "kernel/kernel_double.h"
#include "methods/bruneton.h"
#include "methods/lean.h"
#include "methods/method.h"
#include "methods/microspec.h"
#include "methods/point.h"
#include "methods/reference.h"
#include "methods/specaa.h"
#include "methods/staa.h"
#include "methods/staa_temporal.h"
#include "methods/supersample.h"
#include "methods/taa.h"
#include "shading/path_table_store.h"

namespace sg {

void store_pixel(const FrameContext& ctx, Image& out, int i, int j, const RadianceWeights& w) {
  // Radiances::apply's formula, the kernel's, inlined here: every pixel of every method
  // passes through (out of line, `point` took 4% longer).
  const Radiances& r = ctx.model.radiances;
  for (int c = 0; c < out.channels; ++c)
    out.at(i, j, c) = static_cast<float>(kd::weights_radiance(w, r.channel(c)));
}

void Method::shade_tile(const FrameContext& ctx, int x0, int y0, int x1, int y1, Image& out) const {
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i)
      store_pixel(ctx, out, i, j, weights(ctx, i, j));
  }
}

const std::vector<MethodInfo>& method_catalog() {
  static const std::vector<MethodInfo> catalog = {
      {"reference",
       "ground truth: time integrated exactly per spatial sample on flat water, noise measured "
       "(--samples, 8x8x1; --batches, 2)"},
      {"supersample", "stratified supersampling at a chosen budget (--samples; T=1 samples t_f)"},
      {"point", "one sample at the pixel centre at t_f (no anti-aliasing)"},
      {"staa-temporal",
       "Podee et al. 2021 Sec. 3.3: time in the light along the reflection path "
       "(--segments)"},
      {"staa",
       "Podee et al. 2021: temporal path + aliasing waves as a Gaussian RDF (--ndf, "
       "--kernels, --segments, ...)"},
      {"lean", "LEAN mapping (Olano & Baker 2010): MIP-mapped slope moments, Gaussian NDF at t_f"},
      {"taa", "temporal anti-aliasing: Halton jitter, reprojected history, variance clipping"},
      {"microspec", "micro-specular highlight: brightest corner-quad reflection x disk/quad area"},
      {"specaa", "geometric specular AA: half-vector derivative kernel widens a mirror lobe"},
      {"bruneton", "Bruneton et al. 2010: filtered waves, normals and Ross BRDF with Smith"},
  };
  return catalog;
}

static_assert(MethodOptions{}.intersect_tolerance == kDefaultIntersectTolerance,
              "--intersect-tolerance's default is the kernel frame's");

const PathTables& required_path_tables(const MethodOptions& o, const std::string& method) {
  if (o.path_tables == nullptr) {
    throw Error(method +
                ": no path tables given (MethodOptions::path_tables: the caller creates them, "
                "shading/path_table_store.h)");
  }
  return o.path_tables->tables();
}

std::unique_ptr<Method> make_method(const std::string& name, const MethodOptions& o) {
  validate(o);
  if (name == "reference") {
    return std::make_unique<ReferenceMethod>(reference_settings(o), o.precision);
  }
  if (name == "supersample") {
    return std::make_unique<StratifiedMethod>(
        name, StratifiedSettings{o.samples, o.samples.st == 1}, o.precision,
        stratified_intersect_tolerance(o), o.cascade_fields && o.samples.st == 1);
  }
  if (name == "point")
    return std::make_unique<PointMethod>(o.precision, intersect_tolerance_for(o, name),
                                         o.cascade_fields);
  if (name == "staa-temporal") {
    return std::make_unique<StaaTemporalMethod>(o.staa.segments, o.precision,
                                                intersect_tolerance_for(o, name), o.cascade_fields);
  }
  if (name == "staa") {
    return std::make_unique<StaaMethod>(o.staa, required_path_tables(o, name), o.precision,
                                        intersect_tolerance_for(o, name), o.cascade_fields);
  }
  if (name == "lean") return std::make_unique<LeanMethod>(o.lean, o.precision, o.cascade_fields);
  if (name == "taa")
    return std::make_unique<TaaMethod>(o.taa, o.precision, intersect_tolerance_for(o, name));
  if (name == "microspec") {
    return std::make_unique<MicrospecMethod>(o.microspec, o.precision,
                                             intersect_tolerance_for(o, name));
  }
  if (name == "specaa") {
    return std::make_unique<SpecaaMethod>(o.specaa, o.precision, intersect_tolerance_for(o, name),
                                          o.cascade_fields);
  }
  if (name == "bruneton")
    return std::make_unique<BrunetonMethod>(o.bruneton, o.precision, o.cascade_fields);
  std::string list;
  for (const auto& m : method_catalog())
    list += (list.empty() ? "" : ", ") + m.name;
  throw Error("--method: unknown method '" + name + "' (choose one of: " + list + ")");
}

}  // namespace sg
