// What the viewer changes in a scene while it runs: the camera (moved by
// viewer/view_camera.h), the light's elevation, azimuth and angular radius, and one scale
// on every wave's amplitude, or a sea regenerated from a wind spectrum (wind speed,
// direction, fetch: ocean/ocean.h's JONSWAP with the scene's number of waves, 16 to 4096,
// or, for a scene of cascades, as many cascades of the same lattice: ocean/lattice_ocean.h);
// and the animation time of a
// fractional frame position (slow motion and scrubbing land between frames). The edited
// scene is an ordinary Scene, so saving the view writes it as a scene file that `render`
// reproduces, and an unedited view is the scene itself, bit for bit.
//
// Angles: elevation is the light's angle above the horizontal plane (y up); azimuth is
// measured in the horizontal plane from -z (where the default camera looks) towards +x.
#pragma once

#include "ocean/ocean.h"
#include "scene/model.h"
#include "scene/scene.h"

namespace sg::viewer {

struct ViewEdits {
  double sun_elevation_deg = 0;
  double sun_azimuth_deg = 0;
  double sun_radius_deg = 0.27;
  double amplitude_scale = 1;
  CameraDesc camera;  // the view's camera; edits_of: the scene's, exactly
  // The sea from a spectrum: when `sea` is set, the scene's waves and cascades are replaced
  // by ocean::generate(sea_params) (explicit waves), or, where the scene has cascades, by as
  // many cascades of its first cascade's lattice from ocean::generate_lattice(sea_params)
  // (`sunglint ocean --cascades C --lattice N`); the amplitude scale applies on top.
  bool sea = false;
  ocean::OceanParams sea_params;
};

// The spectrum sea's parameters the viewer starts from for `scene`: JONSWAP, 10 m/s, its
// wave count (explicit waves and the cascades' non-zero lattice points) within [16, 4096].
ocean::OceanParams sea_params_of(const Scene& scene);

// The edits that leave `scene` as it is (its camera, its light's angles, radius, scale 1).
ViewEdits edits_of(const Scene& scene);

// `base` with the edits applied. The light direction is replaced only when the elevation
// or azimuth differ from edits_of(base), so an unedited view keeps the file's direction
// exactly. Throws sg::Error naming the key when the result leaves the scene's ranges
// (the scene's own loader checks it).
Scene edited_scene(const Scene& base, const ViewEdits& edits);

// The shutter interval of frame position `position` (frames from t0, may be fractional):
// frame_time(scene, f) when position is the whole number f, else the interval ending at
// t0 + position / fps.
FrameTime view_time(const Scene& scene, double position);

}  // namespace sg::viewer
