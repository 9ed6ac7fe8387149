// The physical ranges a scene must lie in. The scene spec asks for finite numbers; these
// ranges add what keeps every method well defined (sums finite, phases accurate, the
// displaced march bounded) while admitting every sea sunglint is meant for: wavelengths from
// capillary ripples to ocean swell, thousands of waves of a wind spectrum, the sun's
// radiance, animations of days. The loader (scene_load.cpp) checks them and names the key;
// docs/scene-format-notes.md gives the reason of each.
#pragma once

namespace sg::limits {

// Waves. Wavelength 2 pi / |k| in [1 mm, 100 km]: shorter ripples are damped by viscosity,
// longer waves are tides, not waves on a rendered sea.
inline constexpr double kMinWavelength = 1e-3;  // metres
inline constexpr double kMaxWavelength = 1e5;   // metres
// Steepness A |k| of one sine: Stokes' limit, a crest height of 1/7 of the wavelength
// (A |k| = pi / 7 = 0.449), past which water breaks.
inline constexpr double kMaxSteepness = 0.45;
// The sum of the waves' steepnesses, sum A_i |k_i|: the bound of the surface slope that
// the displaced march steps by (its work grows with it). A wind spectrum of 65536 waves
// sums to about 40; a surface slope of 1000 is a vertical wall.
inline constexpr double kMaxSlopeSum = 1000;
// |angular_frequency|: above the dispersion of the shortest wave, the 1 mm capillary
// ripple (omega^2 = g k + (sigma / rho) k^3: 4257 rad/s).
inline constexpr double kMaxAngularFrequency = 1e4;  // rad/s
// |phase|: an angle; beyond this it adds only rounding.
inline constexpr double kMaxPhase = 1e6;  // rad

// Time. Every time an animation reaches (t0 - shutter/fps to its last frame) within
// +-1e7 s (116 days): the phase c t stays below 1e11 rad, where double rounding is 1e-5 rad.
inline constexpr double kMaxTime = 1e7;     // seconds
inline constexpr double kMinFps = 1e-3;     // one frame in 17 minutes (time lapse)
inline constexpr double kMaxFps = 1e6;      // high-speed cameras
inline constexpr double kMaxShutter = 1.0;  // a 360-degree shutter: the whole interval

// Camera. Within 100 km of the origin and at least 1 mm above the water at rest (the
// shortest wavelength); look_at within 1e7 m (a point on the horizon).
inline constexpr double kMaxCameraDistance = 1e5;  // metres, |camera.position|
inline constexpr double kMinCameraHeight = 1e-3;   // metres
inline constexpr double kMaxLookAtDistance = 1e7;  // metres, |camera.look_at|
inline constexpr double kMinVfov = 1e-3;           // degrees (3.6 arcseconds)
inline constexpr double kMaxVfov = 179;            // degrees
// Direction vectors (light.direction, camera.up): any length in this range (normalised).
inline constexpr double kMinDirectionLength = 1e-12;
inline constexpr double kMaxDirectionLength = 1e12;

// Light: an angular radius from 0.001 degrees (3.6 arcseconds, finer than any planet's
// disk) to 89 degrees (a disk that still lies above the plane its centre faces).
inline constexpr double kMinLightRadius = 1e-3;  // degrees
inline constexpr double kMaxLightRadius = 89;    // degrees

// Radiances (light, sky, sea): >= 0 and at most 1e10, above the sun's luminance in cd/m^2
// (1.6e9 at noon), so absolute photometric units fit. Images hold floats: 1e10 squared and
// summed over 16384^2 pixels is 3e28, far from float's 3.4e38, so metrics, variance
// clipping and glare stay finite.
inline constexpr double kMaxRadiance = 1e10;

// Files: a scene file is read whole; a 65536-wave spectrum is about 14 MB of JSON.
inline constexpr long kMaxSceneFileBytes = 64L << 20;  // 64 MiB

}  // namespace sg::limits
