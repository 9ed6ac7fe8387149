#!/usr/bin/env python3
"""Writes edge/*.json: valid scenes at the edges of the ranges of sunglint-scene/1
(src/scene/scene_limits.h), each derived from scenes/simple.json by one change. Every
method must render each of them with finite pixels, in bounded time (tests/cli/cli_test.sh).
Run from this folder: python3 make_edge_scenes.py"""
import copy, json, math, os

base = json.load(open("../../scenes/simple.json"))
cases = {}

def case(name, edit):
    s = copy.deepcopy(base)
    edit(s)
    cases[name] = s

def below_crests(s):
    # Displaced water whose amplitudes sum to 0.31 m, the camera 5 cm above the water at
    # rest, where the surface is highest at t = 0: under the surface in frame 0.
    s["surface"]["geometry"] = "displaced"
    waves = s["surface"]["waves"]
    total = sum(w["amplitude"] for w in waves)
    for w in waves:
        w["amplitude"] = round(w["amplitude"] * 0.31 / total, 6)
    h = lambda x, z: sum(w["amplitude"] * math.sin(w["wave_vector"][0] * x + w["wave_vector"][1] * z
                                                   + w["phase"]) for w in waves)
    x, z = max(((0.25 * i, 0.25 * j) for i in range(-20, 21) for j in range(-20, 21)),
               key=lambda p: h(*p))
    s["camera"].update(position=[x, 0.05, z], look_at=[x, 0, z - 60])
case("camera_below_crests", below_crests)

def extreme_waves(s):
    # The shortest and the longest wavelength at the breaking steepness, on displaced water.
    s["surface"]["geometry"] = "displaced"
    k = 2 * math.pi / 0.001
    s["surface"]["waves"].append({"amplitude": 0.449 / k, "wave_vector": [k, 0.0],
                                  "angular_frequency": 4257.0, "phase": 0.0})
    k = 2 * math.pi / 1e5
    s["surface"]["waves"].append({"amplitude": 0.01, "wave_vector": [0.0, -k],
                                  "angular_frequency": -0.0248, "phase": 1e6})
case("extreme_waves", extreme_waves)

def bright(s):
    s["light"].update(radiance=1e10, visible=True)
    s["sky"]["radiance"] = 1e10
    s["surface"].update(fresnel="schlick", sea_radiance=1e10)
case("bright_light", bright)

case("late_time", lambda s: s["animation"].update(t0=9.99e6, fps=1e6, shutter=1.0))
case("early_time", lambda s: s["animation"].update(t0=-9.99e6, fps=0.001, frames=1))

def far_camera(s):
    s["camera"].update(position=[7e4, 7e4, 0.0], look_at=[7e4, 0.0, -1e5])
case("far_camera", far_camera)

def low_camera(s):
    s["surface"]["geometry"] = "displaced"
    s["camera"].update(position=[0, 0.001, 0], look_at=[0, 0, -1])
case("low_camera", low_camera)

case("narrow_view", lambda s: s["camera"].update(vfov_deg=0.001, look_at=[0, 0, -60]))
case("wide_view", lambda s: s["camera"].update(vfov_deg=179))
case("tiny_light", lambda s: s["light"].update(angular_radius_deg=0.001))
case("huge_light", lambda s: s["light"].update(angular_radius_deg=89))
case("light_below_horizon", lambda s: s["light"].update(direction=[0, -0.5, -1]))

os.makedirs("edge", exist_ok=True)
for name, s in cases.items():
    with open(f"edge/{name}.json", "w") as f:
        json.dump(s, f, indent=1)
