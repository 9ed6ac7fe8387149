#!/usr/bin/env python3
"""Writes bad/*.json: one scene per validation rule of sunglint-scene/1, /2 and /3, each derived
from scenes/simple.json (a /1 file) by one change (the /2 and /3 cases first set the format). The expected messages live in
src/scene/scene_load_test.cpp. Run from this folder: python3 make_bad_scenes.py"""
import copy, json, os

base = json.load(open("../../scenes/simple.json"))
cases = {}

def case(name, edit):
    s = copy.deepcopy(base)
    edit(s)
    cases[name] = s

case("missing_camera", lambda s: s.pop("camera"))
case("missing_t0", lambda s: s["animation"].pop("t0"))
case("bad_format", lambda s: s.update(format="sunglint-scene/4"))
case("unknown_top_key", lambda s: s.update(foo=1))
case("unknown_camera_key", lambda s: s["camera"].update(fov=40))
case("width_string", lambda s: s["image"].update(width="640"))
case("width_fraction", lambda s: s["image"].update(width=640.5))
case("width_zero", lambda s: s["image"].update(width=0))
case("height_zero", lambda s: s["image"].update(height=0))
case("image_not_object", lambda s: s.update(image=[640, 360]))
case("name_number", lambda s: s.update(name=3))
case("vfov_zero", lambda s: s["camera"].update(vfov_deg=0))
case("vfov_180", lambda s: s["camera"].update(vfov_deg=180))
case("look_at_position", lambda s: s["camera"].update(look_at=s["camera"]["position"]))
case("up_zero", lambda s: s["camera"].update(up=[0, 0, 0]))
case("up_parallel", lambda s: s["camera"].update(up=[0, -2.5, -60]))
case("camera_below_water", lambda s: s["camera"].update(position=[0, -1, 0]))
case("position_two", lambda s: s["camera"].update(position=[0, 2.5]))
case("position_string", lambda s: s["camera"].update(position=[0, "2.5", 0]))
case("light_zero", lambda s: s["light"].update(direction=[0, 0, 0]))
case("light_radius_zero", lambda s: s["light"].update(angular_radius_deg=0))
case("light_radius_90", lambda s: s["light"].update(angular_radius_deg=90))
case("light_radiance_negative", lambda s: s["light"].update(radiance=-1))
case("light_visible_string", lambda s: s["light"].update(visible="yes"))
case("sky_negative", lambda s: s["sky"].update(radiance=-1))
case("geometry_unknown", lambda s: s["surface"].update(geometry="bumpy"))
case("fresnel_unknown", lambda s: s["surface"].update(fresnel="fancy"))
case("sea_negative", lambda s: s["surface"].update(sea_radiance=-0.1))
case("waves_not_array", lambda s: s["surface"].update(waves={"amplitude": 1}))
case("amplitude_negative", lambda s: s["surface"]["waves"][3].update(amplitude=-0.1))
case("wave_vector_three", lambda s: s["surface"]["waves"][0].update(wave_vector=[1, 2, 3]))
case("wave_missing_frequency", lambda s: s["surface"]["waves"][1].pop("angular_frequency"))
case("wave_unknown_key", lambda s: s["surface"]["waves"][2].update(speed=3))
case("wave_not_object", lambda s: s["surface"]["waves"].__setitem__(4, 0.5))
case("fps_zero", lambda s: s["animation"].update(fps=0))
case("frames_zero", lambda s: s["animation"].update(frames=0))
case("shutter_negative", lambda s: s["animation"].update(shutter=-1))
# Physical ranges (src/scene/scene_limits.h).
case("camera_high", lambda s: s["camera"].update(position=[0, 1e308, 0]))
case("camera_far", lambda s: s["camera"].update(position=[2e5, 2.5, 0]))
case("camera_low", lambda s: s["camera"].update(position=[0, 1e-4, 0]))
case("look_at_far", lambda s: s["camera"].update(look_at=[0, 0, -1e8]))
case("up_huge", lambda s: s["camera"].update(up=[0, 1e300, 1e300]))
case("vfov_tiny", lambda s: s["camera"].update(vfov_deg=1e-4))
case("light_huge", lambda s: s["light"].update(direction=[0, 1e200, -1e200]))
case("light_radius_tiny", lambda s: s["light"].update(angular_radius_deg=1e-4))
case("light_radiance_huge", lambda s: s["light"].update(radiance=1e308))
case("sky_huge", lambda s: s["sky"].update(radiance=2e10))
case("sea_huge", lambda s: s["surface"].update(sea_radiance=1e11))
case("wave_vector_huge", lambda s: s["surface"]["waves"][0].update(wave_vector=[1e8, 0]))
case("wave_vector_zero", lambda s: s["surface"]["waves"][1].update(wave_vector=[0, 0]))
case("wavelength_long", lambda s: s["surface"]["waves"][2].update(wave_vector=[1e-6, 0]))
case("amplitude_steep", lambda s: s["surface"]["waves"][0].update(amplitude=1e15))
case("frequency_huge", lambda s: s["surface"]["waves"][3].update(angular_frequency=-1e5))
case("phase_huge", lambda s: s["surface"]["waves"][4].update(phase=1e7))
case("t0_huge", lambda s: s["animation"].update(t0=1e308))
case("frames_past_time", lambda s: s["animation"].update(t0=9.99e6, frames=1000000))
case("shutter_before_time", lambda s: s["animation"].update(t0=-1e7))
case("fps_huge", lambda s: s["animation"].update(fps=1e7))
case("shutter_two", lambda s: s["animation"].update(shutter=2))

# Format /2: colour radiances and the sky gradient; /1 files may not use them.
def v2(edit):
    def f(s):
        s["format"] = "sunglint-scene/2"
        edit(s)
    return f

case("v1_rgb_light", lambda s: s["light"].update(radiance=[1, 0.8, 0.6]))
case("v1_sky_zenith", lambda s: s.update(sky={"zenith": 0.1, "horizon": 0.2}))
case("v1_sky_exponent", lambda s: s["sky"].update(exponent=0.5))
case("v2_rgb_two", v2(lambda s: s["light"].update(radiance=[1, 0.8])))
case("v2_rgb_string", v2(lambda s: s["surface"].update(sea_radiance="blue")))
case("v2_rgb_element_string", v2(lambda s: s["light"].update(radiance=[1, "0.8", 0.6])))
case("v2_rgb_negative", v2(lambda s: s["sky"].update(radiance=[0.1, -0.2, 0.3])))
case("v2_sea_negative", v2(lambda s: s["surface"].update(sea_radiance=-0.01)))
case("v2_sky_both_forms",
     v2(lambda s: s["sky"].update(radiance=0.1, zenith=[0.05, 0.1, 0.3], horizon=0.4)))
case("v2_sky_zenith_only", v2(lambda s: s.update(sky={"zenith": [0.05, 0.1, 0.3]})))
case("v2_sky_horizon_only", v2(lambda s: s.update(sky={"horizon": 0.4})))
case("v2_sky_exponent_zero",
     v2(lambda s: s.update(sky={"zenith": 0.1, "horizon": 0.4, "exponent": 0})))
case("v2_sky_exponent_string",
     v2(lambda s: s.update(sky={"zenith": 0.1, "horizon": 0.4, "exponent": "0.5"})))
case("v2_sky_exponent_constant", v2(lambda s: s["sky"].update(exponent=0.5)))
case("v2_sky_horizon_negative",
     v2(lambda s: s.update(sky={"zenith": 0.1, "horizon": [0.4, 0.3, -1]})))
case("v2_sky_unknown_key", v2(lambda s: s.update(sky={"zenith": 0.1, "horizon": 0.4, "color": 1})))

# Format /3: camera keyframes (a pan from simple's camera).
def v3(keys, **camera):
    def f(s):
        s["format"] = "sunglint-scene/3"
        c = s["camera"]
        c.pop("position")
        c.pop("look_at")
        c["keyframes"] = [{"time": t, "position": p, "look_at": a} for t, p, a in keys]
        c.update(camera)
    return f

pan = [(0.0, [0, 2.5, 0], [-10, 0, -60]), (2.0, [0, 2.5, -4], [10, 0, -60])]
case("v2_keyframes", v2(lambda s: s["camera"].update(keyframes=[])))
case("v3_keyframes_and_position",
     v3(pan, position=[0, 2.5, 0]))
case("v3_keyframes_one", v3(pan[:1]))
case("v3_keyframes_not_array", v3(pan, keyframes={"time": 0}))
case("v3_keyframe_unknown_key",
     lambda s: (v3(pan)(s), s["camera"]["keyframes"][1].update(roll=3)))
case("v3_keyframe_time_equal", v3(pan + [(2.0, [0, 2.5, -5], [0, 0, -60])]))
case("v3_keyframe_time_decreasing", v3(pan + [(1.0, [0, 2.5, -5], [0, 0, -60])]))
case("v3_keyframe_time_missing", lambda s: (v3(pan)(s), s["camera"]["keyframes"][0].pop("time")))
case("v3_keyframe_below_water", v3([pan[0], (2.0, [0, -1, -4], [10, 0, -60])]))
case("v3_keyframe_look_at_position", v3([pan[0], (2.0, [0, 2.5, -4], [0, 2.5, -4])]))
case("v3_keyframe_up_parallel", v3([pan[0], (2.0, [0, 2.5, -4], [0, -10, -4])]))
# Good keys, but the interpolated camera meets its look-at point (the view vector
# (0, 0, -10) turns to (0, 0, 10) through zero at t = 1) or looks along `up` (the view
# (5, -3, 0) turns to (-5, -3, 0) through (0, -3, 0) at t = 1) between them.
case("v3_segment_meets_look_at",
     v3([(0.0, [0, 3, 0], [0, 3, -10]), (2.0, [0, 3, -10], [0, 3, 0])]))
case("v3_segment_up_parallel",
     v3([(0.0, [0, 3, 0], [5, 0, 0]), (2.0, [0, 3, 0], [-5, 0, 0])]))

os.makedirs("bad", exist_ok=True)
for name, s in cases.items():
    with open(f"bad/{name}.json", "w") as f:
        json.dump(s, f, indent=1)
# Cases that JSON values cannot express.
text = json.dumps(base, indent=1)
with open("bad/amplitude_infinite.json", "w") as f:
    f.write(text.replace('"amplitude": 0.038197', '"amplitude": 1e999', 1))
# A duplicate key: JSON parsers differ on which value wins, so it is an error.
with open("bad/duplicate_key.json", "w") as f:
    f.write(text.replace('"amplitude": 0.095493,', '"amplitude": 0.095493,\n    "amplitude": 0.2,', 1))
with open("bad/duplicate_top_key.json", "w") as f:
    f.write(text.replace('"name": "simple",', '"name": "simple",\n "name": "other",', 1))
with open("bad/syntax_error.json", "w") as f:
    f.write(text.replace('"fps": 30,', '"fps": 30', 1))
with open("bad/top_level_array.json", "w") as f:
    f.write("[" + text + "]")
gradient = copy.deepcopy(base)
gradient["format"] = "sunglint-scene/2"
gradient["sky"] = {"zenith": [0.05, 0.1, 0.3], "horizon": 0.4, "exponent": 12345}
with open("bad/v2_sky_exponent_infinite.json", "w") as f:
    f.write(json.dumps(gradient, indent=1).replace("12345", "1e999", 1))
moving = copy.deepcopy(base)
v3([(0.0, [0, 2.5, 0], [-10, 0, -60]), (12345.0, [0, 2.5, -4], [10, 0, -60])])(moving)
with open("bad/v3_keyframe_time_infinite.json", "w") as f:
    f.write(json.dumps(moving, indent=1).replace("12345.0", "1e999", 1))
