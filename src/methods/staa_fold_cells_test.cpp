// `staa --fold-cells`: a lit pixel where a resolved wave's slope turns across it (its
// departure from the tangent above X disk radii) is shaded as the mean of its four quarters,
// each a pixel of half the size with its own centre, footprint and wave pass
// (kernel/staa.glsl, staa_pixel). The cut pixels are the mean of the pixels of a render at
// twice the resolution, the others the uncut render's; on a glint that a steep swell folds
// within a pixel (tests/scenes/fold-glint.json: `sea21` of the random seas, seed 1, whose
// 10.5 m swell spans a quarter of a cycle of a pixel 2.6 m long) the quarters follow the
// fold that the footprint term's linear normals miss (docs/method.md, "A steep resolved
// wave that turns its slope across the pixel"). Broken on purpose once each (2026-12-07): the
// quarters' derivatives not halved fail the first (within 3.3e-3 of the quarters' mean, not
// 1e-9); the quarters computed and not taken fail both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "engine/render.h"
#include "methods/method.h"
#include "methods/staa.h"
#include "metrics/metrics.h"
#include "scene/scene.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg {
namespace {

Scene fold_scene() {
  return load_scene(testing::source_dir() + "/tests/scenes/fold-glint.json");
}

Image render_staa(const Scene& s, double fold_cells, int frame) {
  StaaOptions o;
  o.fold_cells = fold_cells;
  StaaMethod staa(o, testing::path_tables());
  return render_frame(SceneModel(s), staa, frame, {});
}

TEST(StaaFoldCells, CutPixelsAreTheMeanOfTheirQuarters) {
  Scene s = fold_scene();
  s.width = 32;
  s.height = 18;
  // A limit far below any wave's: every lit pixel is cut.
  const Image cut = render_staa(s, 1e-9, 1), whole = render_staa(s, 0, 1);
  Scene fine = s;
  fine.width = 2 * s.width;
  fine.height = 2 * s.height;
  const Image quarters = render_staa(fine, 0, 1);
  int cut_pixels = 0;
  double worst = 0, moved = 0;  // |cut - mean of quarters| and |whole - mean| over the cut
  for (int j = 0; j < cut.height; ++j) {
    for (int i = 0; i < cut.width; ++i) {
      double mean = 0;
      for (int q = 0; q < 4; ++q)
        mean += 0.25 * quarters.at(2 * i + (q & 1), 2 * j + (q >> 1), 0);
      const double v = cut.at(i, j, 0), w = whole.at(i, j, 0);
      const double tol = 1e-9 + 1e-6 * std::max(std::abs(mean), std::abs(w));
      if (std::abs(v - w) <= tol) continue;  // not cut (or cut to the same value)
      ++cut_pixels;
      worst = std::max(worst, std::abs(v - mean));
      moved = std::max(moved, std::abs(w - mean));
      EXPECT_NEAR(v, mean, tol) << "pixel (" << i << ", " << j << ")";
    }
  }
  std::printf(
      "%d of %d pixels cut; the cut within %.3g of their quarters' mean, which lies up to "
      "%.3g from the uncut pixel\n",
      cut_pixels, cut.width * cut.height, worst, moved);
  EXPECT_GE(cut_pixels, 3);                           // the glitter's pixels
  EXPECT_LE(cut_pixels, cut.width * cut.height / 4);  // not the unlit sky and sea
  EXPECT_GT(moved, 1e3 * worst);                      // the quarters differ from the whole
}

TEST(StaaFoldCells, TheQuartersFollowAFoldedGlint) {
  const Scene s = fold_scene();
  const SceneModel m(s);
  MethodOptions o;
  o.samples = SampleCounts{16, 16, 1};
  o.samples_given = true;
  o.adaptive = false;
  std::unique_ptr<Method> ref = make_method("reference", testing::with_tables(o));
  std::vector<Image> r, whole, cells;
  for (int f = 0; f < 3; ++f) {
    r.push_back(render_frame(m, *ref, f, {}));
    whole.push_back(render_staa(s, 0, f));
    cells.push_back(render_staa(s, 1, f));
  }
  const SequenceMetrics a = compare_sequences(whole, r), b = compare_sequences(cells, r);
  std::printf("fold-glint: RMSE %.3g -> %.3g, temporal %.3g -> %.3g with the quarters\n", a.rmse,
              b.rmse, a.temporal_error, b.temporal_error);
  // Measured (a 32x32x1 reference): 6.8e-4 -> 8.7e-5 and 2.1e-4 -> 6.0e-5.
  EXPECT_GT(a.rmse, 4e-4);  // the scene holds the fold the footprint term misses
  EXPECT_LT(b.rmse, 1.5e-4);
  EXPECT_LT(b.temporal_error, 1e-4);
}

}  // namespace
}  // namespace sg
