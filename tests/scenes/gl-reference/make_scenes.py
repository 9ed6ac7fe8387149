#!/usr/bin/env python3
"""Writes the scenes on which the GL engine's reference once disagreed with the CPU's
(docs/reference-renderer.md: "Float crossings"): small flat seas, lit from the
side or under a Schlick-Fresnel sky, that the shared scenes of scenes/ (sun straight
ahead, no sky) never exercised. gl_engine_test renders them with both engines and checks
the image means agree within 4 standard errors; long-shutter is one whose shutter
the reference cuts into windows. Deterministic; run from this folder:
python3 make_scenes.py"""
import json, math, random


def waves(n, seed, lambda_min, lambda_max, steepness):
    # n waves crossing from every direction, log-spaced wavelengths, deep-water dispersion,
    # each with slope amplitude A |k| = steepness / sqrt(n).
    rng = random.Random(seed)
    out = []
    for i in range(n):
        lam = lambda_min * (lambda_max / lambda_min) ** ((i + rng.random()) / n)
        k = 2 * math.pi / lam
        d = 2 * math.pi * rng.random()
        out.append({"amplitude": round(steepness / math.sqrt(n) / k, 6),
                    "wave_vector": [round(k * math.cos(d), 6), round(k * math.sin(d), 6)],
                    "angular_frequency": round(math.sqrt(9.81 * k), 6),
                    "phase": round(2 * math.pi * rng.random(), 6)})
    return out


def light_dir(elevation_deg, azimuth_deg):
    # Azimuth from the view's direction (-z), positive to the right (+x).
    e, a = math.radians(elevation_deg), math.radians(azimuth_deg)
    return [round(math.cos(e) * math.sin(a), 6), round(math.sin(e), 6),
            round(-math.cos(e) * math.cos(a), 6)]


def scene(name, light, sky, fresnel, sea, wave_list, camera_height=2.5, look_at=60.0, fps=30):
    return {
        "format": "sunglint-scene/2", "name": name,
        "image": {"width": 160, "height": 90},
        "camera": {"position": [0, camera_height, 0], "look_at": [0, 0, -look_at], "up": [0, 1, 0],
                   "vfov_deg": 40.0},
        "light": light, "sky": sky,
        "surface": {"geometry": "flat", "fresnel": fresnel, "sea_radiance": sea,
                    "waves": wave_list},
        "animation": {"t0": 0.0, "fps": fps, "frames": 10, "shutter": 1.0},
    }


# The sun 40 degrees up and 60 degrees to the right of the view, 64 steep waves crossing,
# seen from 20 m up: sparse glints from facets tilted far from the mirror direction.
side = scene("side-sun",
             {"direction": light_dir(40, 60), "angular_radius_deg": 0.27, "radiance": 1.0,
              "visible": False},
             {"radiance": 0.0}, "none", 0.0, waves(64, 22, 0.3, 30.0, 0.8),
             camera_height=20.0, look_at=25.0)
# Schlick Fresnel, a constant sky 0.02, sea 0.005 and the sun ahead, 12 degrees up.
fresnel = scene("fresnel-light",
                {"direction": light_dir(12, 0), "angular_radius_deg": 0.27, "radiance": 1.0,
                 "visible": False},
                {"radiance": 0.02}, "schlick", 0.005, waves(16, 7, 0.5, 40.0, 0.25))
# A 10 s shutter (fps 0.1) over 32 waves with periods of 0.8 to 5 s, Schlick Fresnel under
# a sky gradient: 32 sub-intervals cannot follow the normals' path over the whole shutter,
# so the reference integrates windows of it (kernel/reference.glsl; before, on such a
# random scene, the water came out at 0.2 of its value on both engines).
long_shutter = scene("long-shutter",
                     {"direction": light_dir(15, 10), "angular_radius_deg": 0.27, "radiance": 1.0,
                      "visible": False},
                     {"zenith": 0.05, "horizon": 0.01, "exponent": 0.5}, "schlick", 0.005,
                     waves(32, 11, 1.0, 40.0, 0.3), fps=0.1)
for s in (side, fresnel, long_shutter):
    with open(s["name"] + ".json", "w") as f:
        json.dump(s, f, indent=1)
        f.write("\n")
