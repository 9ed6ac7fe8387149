#!/usr/bin/env python3
"""The scenes of the aliasing study (docs/aliasing-study.md): views where the pixel's
footprint spans many wavelengths, so that most waves alias and staa reduces to a Gaussian
of normals, as lean does. Deterministic (fixed seed); run from this folder to rewrite them.

- cross-swell-side.json: two swells 70 degrees apart with a short wind sea on top, the
  sun 25 degrees up and 40 degrees to the right of the view;
- grazing-moon.json: the moon 3 degrees up straight ahead over medium's sea, camera 4 m up;
- high-sun-above.json: the sun 62 degrees up, 10 degrees to the right, camera 40 m up
  looking 35 degrees down on a wind sea;
- elevation-NN.json: the light's elevation swept over one view, grazing-moon's sea and
  camera under the sun (0.27 degrees) NN = 2, 5, 10, 15 and 20 degrees up straight ahead
  (the view's lower edge is 20 degrees down: higher suns reflect out of the frame).
"""
import json
import math
import random

G = 9.81


def wave(rng, wavelength, direction_deg, slope):
    k = 2 * math.pi / wavelength
    a = math.radians(direction_deg)
    return {
        "amplitude": round(slope / k, 6),
        "wave_vector": [round(k * math.sin(a), 6), round(-k * math.cos(a), 6)],
        "angular_frequency": round(math.sqrt(G * k), 6),
        "phase": round(rng.uniform(0, 2 * math.pi), 6),
    }


def band(rng, n, lo, hi, centre_deg, spread_deg, slope):
    out = []
    for i in range(n):
        lam = lo * (hi / lo) ** ((i + 0.5) / n)
        out.append(wave(rng, lam, centre_deg + rng.uniform(-spread_deg, spread_deg), slope))
    return out


def light(elev_deg, azim_deg):
    e, a = math.radians(elev_deg), math.radians(azim_deg)
    return [round(math.cos(e) * math.sin(a), 6), round(math.sin(e), 6),
            round(-math.cos(e) * math.cos(a), 6)]


def scene(name, cam_pos, look_at, waves, light_dir, radius, vfov=40.0):
    return {
        "format": "sunglint-scene/1",
        "name": name,
        "image": {"width": 640, "height": 360},
        "camera": {"position": cam_pos, "look_at": look_at, "up": [0, 1, 0],
                   "vfov_deg": vfov},
        "light": {"direction": light_dir, "angular_radius_deg": radius, "radiance": 1.0,
                  "visible": False},
        "sky": {"radiance": 0.0},
        "surface": {"geometry": "flat", "fresnel": "none", "sea_radiance": 0.0,
                    "waves": waves},
        "animation": {"t0": 0.0, "fps": 30, "frames": 60, "shutter": 1.0},
    }


def main():
    rng = random.Random(29)
    cross = (band(rng, 8, 12.0, 40.0, 30.0, 8.0, 0.07) + band(rng, 8, 10.0, 35.0, -40.0, 8.0, 0.06)
             + band(rng, 24, 0.3, 4.0, 0.0, 60.0, 0.05))
    moon_sea = band(rng, 48, 0.5, 20.0, 0.0, 50.0, 0.06)
    wind = band(rng, 48, 0.4, 30.0, 20.0, 45.0, 0.065)
    scenes = [
        scene("cross-swell-side", [0, 3.0, 0], [0, 0, -60.0], cross, light(25, 40), 0.27),
        scene("grazing-moon", [0, 4.0, 0], [0, 0, -60.0], moon_sea, light(3, 0), 0.26),
        scene("high-sun-above", [0, 40.0, 0], [0, 0, -57.1], wind, light(62, 10), 0.27),
    ]
    scenes += [scene(f"elevation-{e:02d}", [0, 4.0, 0], [0, 0, -60.0], moon_sea, light(e, 0), 0.27)
               for e in (2, 5, 10, 15, 20)]
    for s in scenes:
        with open(s["name"] + ".json", "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
