// What the target tests that measure a method against a stored reference share
// (methods/displaced_targets_test.cpp, methods/aliasing_targets_test.cpp): the stored
// frames and their per-pixel variances (tests/data/<folder>/<stem>_NN.exr and
// <stem>_variance_NN.exr, each folder's README has the command that wrote them), a
// method's frames 0..N-1 rendered in order, and an error with the reference's noise taken
// out, and supersampling measured against the stored frames.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "engine/render.h"
#include "image/image_io.h"
#include "methods/method.h"
#include "metrics/metrics.h"
#include "testing/path_tables.h"
#include "testing/testing.h"

namespace sg::testing {

struct StoredReference {
  std::vector<Image> frames, variances;
};

// Frames 0..count-1 of tests/data/<folder>/<stem>_NN.exr and their variances, each checked
// to be width x height (a failed check is a test failure; the frames read so far return).
inline StoredReference read_stored_reference(const std::string& folder, const std::string& stem,
                                             int count, int width, int height) {
  StoredReference r;
  const std::string dir = source_dir() + "/tests/data/" + folder + "/";
  char file[128];
  for (int f = 0; f < count; ++f) {
    std::snprintf(file, sizeof file, "%s_%02d.exr", stem.c_str(), f);
    r.frames.push_back(read_image(dir + file));
    std::snprintf(file, sizeof file, "%s_variance_%02d.exr", stem.c_str(), f);
    r.variances.push_back(read_image(dir + file));
    EXPECT_EQ(r.frames.back().width, width) << file;
    EXPECT_EQ(r.frames.back().height, height) << file;
  }
  return r;
}

// `method`'s frames 0..count-1 of m, rendered in order (the path tables from the test
// cache).
inline std::vector<Image> render_sequence(const SceneModel& m, const std::string& method,
                                          const MethodOptions& o, int count) {
  std::vector<Image> out;
  std::unique_ptr<Method> p = make_method(method, with_tables(o));
  for (int f = 0; f < count; ++f)
    out.push_back(render_frame(m, *p, f, {}));
  return out;
}

// An RMS error e with the reference's noise variance noise2 taken out: se^2 for an RMSE,
// 2 se^2 for a temporal error (two frames' independent noise).
inline double noise_corrected(double e, double noise2) {
  return std::sqrt(std::max(0.0, e * e - noise2));
}

// `supersample --samples S` over frames 0..count-1 of m against the stored frames `ref`
// (standard error se), its RMSE with the noise taken out, printed with its scene's name:
// what the target tests state as a constant and render again on request.
inline double measure_supersample_rmse(const SceneModel& m, const std::vector<Image>& ref,
                                       double se, SampleCounts samples, int count,
                                       const std::string& scene) {
  MethodOptions ss;
  ss.samples = samples;
  ss.samples_given = true;
  const SequenceMetrics mss = compare_sequences(render_sequence(m, "supersample", ss, count), ref);
  const double rmse = noise_corrected(mss.rmse, se * se);
  std::printf("%-14s supersample %s: RMSE %.4g (%.4g corrected), temporal %.4g\n", scene.c_str(),
              to_string(samples).c_str(), mss.rmse, rmse, mss.temporal_error);
  return rmse;
}

}  // namespace sg::testing
