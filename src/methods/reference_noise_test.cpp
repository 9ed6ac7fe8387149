// The reference's estimate of its own noise (methods/reference.h): the standard error it
// reports from the spread of its batches against the spread of 16 renders with
// independent seeds, on flat water (time integrated exactly: spatial noise only) and on
// displaced water (sampled in space and time), each within 25%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/render.h"
#include "methods/reference.h"
#include "testing/testing.h"

namespace sg {
namespace {

struct NoiseFigures {
  double reported = 0;  // RMS over the seeds of the standard error each render reports
  double spread = 0;    // sqrt(mean over the values of their variance over the seeds)
};

NoiseFigures noise_over_seeds(const Scene& s, const ReferenceSettings& settings, int seeds) {
  const SceneModel m(s);
  std::vector<Image> images;
  double reported = 0;
  for (int k = 0; k < seeds; ++k) {
    ReferenceMethod ref(settings);
    RenderSettings rs;
    rs.seed = uint64_t(1000 + 17 * k);
    images.push_back(render_frame(m, ref, 3, rs));
    reported += sqr(image_standard_error(*ref.pixel_variance()));
  }
  NoiseFigures f;
  f.reported = std::sqrt(reported / seeds);
  double var = 0;
  const size_t n = images.front().size();
  for (size_t v = 0; v < n; ++v) {
    double mean = 0, sq = 0;
    for (const Image& img : images)
      mean += img.data[v] / seeds;
    for (const Image& img : images)
      sq += sqr(img.data[v] - mean);
    var += sq / (seeds - 1);
  }
  f.spread = std::sqrt(var / double(n));
  return f;
}

TEST(ReferenceNoise, StandardErrorMatchesTheSpreadOfSixteenSeedsOnFlatWater) {
  Scene s = testing::project_scene("medium");
  s.width = 96;
  s.height = 54;
  ReferenceSettings st;
  st.samples = {2, 2, 1};
  st.batches = 2;
  const NoiseFigures f = noise_over_seeds(s, st, 16);
  std::printf("flat: reported standard error %.4g, spread of 16 seeds %.4g (ratio %.3f)\n",
              f.reported, f.spread, f.reported / f.spread);
  ASSERT_GT(f.spread, 1e-5);
  EXPECT_NEAR(f.reported / f.spread, 1.0, 0.25);
}

TEST(ReferenceNoise, StandardErrorMatchesTheSpreadOfSixteenSeedsOnDisplacedWater) {
  Scene s = testing::displaced_variant(testing::project_scene("smooth"));
  s.width = 48;
  s.height = 27;
  ReferenceSettings st;
  st.samples = {1, 1, 1};
  st.batches = 4;
  const NoiseFigures f = noise_over_seeds(s, st, 16);
  std::printf("displaced: reported standard error %.4g, spread of 16 seeds %.4g (ratio %.3f)\n",
              f.reported, f.spread, f.reported / f.spread);
  ASSERT_GT(f.spread, 1e-5);
  EXPECT_NEAR(f.reported / f.spread, 1.0, 0.25);
}

}  // namespace
}  // namespace sg
