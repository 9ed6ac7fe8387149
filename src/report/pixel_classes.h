// What each pixel sees, for splitting a method's error by it (`sunglint compare --split`):
// where on displaced water a method errs is a question of geometry, and the classes below
// are the geometric situations in which a pixel's first-order model of the water (one
// hit point, its tangent plane, the ray differentials transferred onto it: kernel/
// footprint.glsl) stops describing what the pixel's rays meet.
//
// At the frame's display time, on the kernel's own geometry (the double kernel: camera,
// intersection, gradient), each pixel is traced through its centre and through a 3 x 3
// grid of points inside it (cell centres), with the displaced intersection's tolerance
// the methods use (`tolerance`, pixels; kernel/intersect.glsl). Let c be the centre's hit,
// m the resolved surface's normal there, L = max(|dp/dpx|, |dp/dpy|) the footprint's
// longer side (metres) and, for each grid ray, s_hit its hit and s_plane its meeting with
// the tangent plane at c (parameters along the unit ray). The first class that applies:
//   sky            no ray meets the water;
//   horizon        some rays meet the water, some do not (the horizon, or a last crest
//                  against the sky);
//   nearer crest   a grid ray meets the water more than L before the tangent plane
//                  (s_hit < s_plane - L): a crest in front hides part of the footprint;
//   over a crest   a grid ray meets the water more than L beyond the plane, or never
//                  meets the plane (the footprint wraps over a crest or a face turned
//                  away: the rays reach water the tangent plane does not hold);
//   left-out waves the centre's hit with every wave (tolerance 0) is more than L from
//                  the hit with the tolerance: the waves the intersection leaves out
//                  moved the seen point by more than the footprint (their bound holds
//                  to first order only; grazes break it);
//   tilted face    the face is turned away from the camera so that the footprint is more
//                  than twice as long as on the water at rest: the ray's sine to the
//                  tangent plane, |d . m| / |m|, below half its sine to the plane y = 0;
//   plain          the rest: one face, moderately tilted, the first-order model holds.
// On flat water only sky, horizon and plain occur.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "scene/model.h"

namespace sg {

enum class PixelClass : unsigned char {
  sky = 0,
  horizon,
  nearer_crest,
  over_crest,
  left_out_waves,
  tilted_face,
  plain,
};
inline constexpr int kPixelClasses = 7;
inline constexpr std::array<const char*, kPixelClasses> kPixelClassNames = {
    "sky", "horizon", "nearer crest", "over a crest", "left-out waves", "tilted face", "plain"};

struct PixelClasses {
  int width = 0, height = 0;
  std::vector<unsigned char> of;            // PixelClass per pixel, row-major
  std::array<long, kPixelClasses> count{};  // pixels per class
  // A mask per class (nonzero: the pixel is in it), for metrics/metrics.h.
  std::vector<unsigned char> mask(PixelClass c) const;
};

// The classes of frame `ft`'s pixels; `model` is the frame's (scene/camera_path.h,
// frame_model, for a moving camera). Rows run on `threads` threads (0: all).
PixelClasses classify_pixels(const SceneModel& model, const FrameTime& ft, double tolerance,
                             int threads = 0);

}  // namespace sg
