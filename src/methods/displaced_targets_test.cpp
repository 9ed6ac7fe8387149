// `staa` on displaced water against its targets (docs/targets.md, "Displaced water"): on
// tests/scenes/displaced-swell.json and displaced-wind.json at 160x90, frames 0-9, against
// a stored reference (tests/data/displaced-targets/: `reference --samples 24x24x1`, 2
// batches, and each pixel's variance; tests/data/displaced-targets/README.md has the
// command), `staa`'s RMSE at most 0.7 of `supersample --samples 6x6x1`'s and its temporal
// error at most 0.1 of `point`'s. Measured (2026-12-06, the reference and `supersample`
// intersecting every wave and `staa` weighting its normals by their projected area,
// docs/method.md): RMSE ratios 0.425 (swell) and 0.296 (wind sea), temporal-error ratios
// 0.095 and 0.055 with the reference's noise taken out (0.108 and 0.064 as measured); with
// `supersample` on the 0.25-pixel tolerance (0.25 / 6 per sample cell), 0.423 and 0.288.
// 2026-12-04, against the
// reference of the 0.25-pixel tolerance: 0.426 and 0.289, temporal 0.096 and 0.055 (0.102
// and 0.060 before that, when the swell missed 0.1 by 2%): both met,
// and the test holds both at the targets. `point`'s
// temporal error here is that of a handful of pixels that catch the sun in some frames
// and not in others, so it moves by a third when one of them does.
//
// The reference is stored because a displaced reference fine enough to measure `staa`
// against costs minutes a frame (11 s and 19 s a frame at 160x90 on two cores); `staa` and
// `point` are rendered here (about 50 ms a frame each). `supersample 6x6x1` costs seconds a
// frame, so its RMSE against the same stored frames is stated below as measured
// (SG_DISPLACED_TARGETS_MEASURE=1 renders it and prints it again). The reference's noise
// is taken out of the RMSEs, sqrt(max(0, RMSE^2 - se^2)), and out of the temporal errors,
// sqrt(max(0, e^2 - 2 se^2)) (two frames' independent noise), se from the stored variances.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/render.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "methods/reference.h"
#include "metrics/metrics.h"
#include "testing/stored_reference.h"

namespace sg {
namespace {

constexpr int kFrames = 10;

using testing::noise_corrected;

struct Target {
  const char* scene;
  double supersample_rmse;  // noise-corrected, measured against the stored reference
};

TEST(DisplacedTargets, StaaAgainstSupersamplingAndPointOnDisplacedSeas) {
  const bool measure = std::getenv("SG_DISPLACED_TARGETS_MEASURE") != nullptr;
  // supersample 6x6x1's RMSE, noise taken out, as SG_DISPLACED_TARGETS_MEASURE=1 printed it.
  for (const Target t : {Target{"swell", 0.001406}, Target{"wind", 0.001154}}) {
    const std::string name = t.scene;
    Scene s = load_scene(testing::source_dir() + "/tests/scenes/displaced-" + name + ".json");
    set_image_size(s, 160, 90);
    const SceneModel m(s);
    const testing::StoredReference stored =
        testing::read_stored_reference("displaced-targets", t.scene, kFrames, 160, 90);
    if (HasFailure()) return;
    const std::vector<Image>& ref = stored.frames;
    const double se = sequence_standard_error(stored.variances);
    const std::vector<Image> staa = testing::render_sequence(m, "staa", {}, kFrames);
    const std::vector<Image> point = testing::render_sequence(m, "point", {}, kFrames);
    const SequenceMetrics ms = compare_sequences(staa, ref), mp = compare_sequences(point, ref);
    const double super = measure ? testing::measure_supersample_rmse(
                                       m, ref, se, SampleCounts{6, 6, 1}, kFrames, t.scene)
                                 : t.supersample_rmse;
    const double rs = noise_corrected(ms.rmse, se * se);
    const double ts = noise_corrected(ms.temporal_error, 2 * se * se),
                 tp = noise_corrected(mp.temporal_error, 2 * se * se);
    std::printf(
        "%-6s reference se %.3g; staa RMSE %.4g (%.4g corrected) / supersample %.4g: %.3f; "
        "temporal error staa %.4g (%.4g corrected), point %.4g (%.4g): %.3f (as measured "
        "%.3f)\n",
        t.scene, se, ms.rmse, rs, super, rs / super, ms.temporal_error, ts, mp.temporal_error, tp,
        ts / tp, ms.temporal_error / mp.temporal_error);
    EXPECT_LE(rs, 0.7 * super) << name;
    EXPECT_LE(ts, 0.1 * tp) << name;
    EXPECT_LT(se, 0.5 * super) << name
                               << ": the reference must be finer than supersampling's error";
  }
}

}  // namespace
}  // namespace sg
