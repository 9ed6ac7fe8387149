#!/usr/bin/env python3
"""`sunglint render -m point` against spec_point.py, an independent reading of
docs/scene-format.md: a fixed, seeded set of small scenes (formats /1, /2, /3; flat and
displaced water; Fresnel none and Schlick; constant and gradient skies in grey and RGB; sea
radiance; the light in front, to the side, behind and overhead, 0.27 to 15 degrees, drawn in
view where light.visible, and low in front over calm water, mirrored by many pixels; level,
steep, grazing and rolled cameras; t0 != 0, frame 0 and later; /3 cameras that move and turn,
t_f before, between and after their keyframes), each rendered by sunglint and compared pixel
by pixel with the Python value:

    |sunglint - python| <= 1e-5 * max(1, |python|) in every channel of every pixel,

except the pixels whose centre sample lies within MARGIN of a discontinuity of the radiance
(the light disk's rim, r.y = 0, the horizon) or whose hit is ill-conditioned (a displaced
crest grazed, far water near the horizon: spec_point.Scene.hit_is_unstable),
where two correct renderers may round to different sides. Those exclusions are counted and
must stay under MAX_EXCLUDED of the pixels, so that they cannot hide a systematic error.

Usage: spec_point_test.py SUNGLINT OUTDIR   (exit 0 when every compared pixel agrees)
"""
import json
import math
import os
import random
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spec_point  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import pfm  # noqa: E402

TOLERANCE = 1e-5      # relative to max(1, |value|); PFM holds float32 (6e-8 relative)
MARGIN = 1e-7         # rad (sine of an angle): closer to a discontinuity is left out
MAX_EXCLUDED = 0.01   # of all pixels
SEED = 20261206
D2R = math.pi / 180


# ---- the scenes ----------------------------------------------------------------------------
def random_waves(rng, n, steepness):
    """n waves around one direction, wavelengths 2-20 m, steepness A k in `steepness`."""
    out, base = [], rng.uniform(0, 2 * math.pi)
    for _ in range(n):
        th = base + rng.gauss(0, 0.8)
        k = math.exp(rng.uniform(math.log(0.3), math.log(3.0)))
        out.append({"amplitude": round(rng.uniform(*steepness) / k, 6),
                    "wave_vector": [round(k * math.cos(th), 6), round(k * math.sin(th), 6)],
                    "angular_frequency": round(math.sqrt(9.81 * k) * rng.uniform(0.8, 1.2), 6),
                    "phase": round(rng.uniform(0, 2 * math.pi), 6)})
    return out


def direction(yaw, pitch):
    return [math.sin(yaw) * math.cos(pitch), math.sin(pitch), -math.cos(yaw) * math.cos(pitch)]


def random_colour(rng, fmt, lo, hi):
    if fmt == 1 or rng.random() < 0.25:
        return round(rng.uniform(lo, hi), 5)  # a number: grey
    return [round(rng.uniform(lo, hi), 5) for _ in range(3)]


def make_scene(k, rng, moving=None, glitter=False):
    """Scene number k: its features cycle with k (format k % 3, light k % 5, camera k % 4,
    displaced for k % 7 in 1, 3, 5), the rest is drawn from rng. `moving` forces a /3 camera
    that moves and turns fast (keys: where t_f sits, swing of the look-at point in m);
    `glitter` a large light low in front, the camera looking at its path on calm water.
    Returns (name, scene dict, frame)."""
    fmt = 3 if moving else [1, 2, 3][k % 3]
    light_kind = "glitter" if glitter else \
        ["front_low", "side", "behind", "overhead", "front_visible"][k % 5]
    cam_kind = "glitter" if glitter else ["horizon", "steep", "rolled", "grazing"][k % 4]
    if light_kind == "front_visible":
        cam_kind = "horizon" if k % 2 else "rolled"
    if light_kind == "overhead" and cam_kind == "horizon":
        cam_kind = "steep"
    displaced = k % 7 in (1, 3, 5)
    width, height = (40, 24) if glitter else [(40, 24), (32, 18), (24, 14), (36, 22)][(k // 3) % 4]
    name = "s%02d_f%d_%s_%s" % (k, fmt, light_kind if glitter else light_kind + "_" + cam_kind,
                                "disp" if displaced else "flat")

    # Camera: the pitch of the view direction sets how much sky and how far the water reaches.
    yaw, vfov = rng.uniform(-math.pi, math.pi), rng.uniform(30, 60)
    up = [0, 1, 0]
    if cam_kind == "horizon":
        pitch = -rng.uniform(0, 0.3) * vfov * D2R
    elif cam_kind == "steep":
        pitch = -rng.uniform(45, 80) * D2R
    elif cam_kind == "rolled":  # up tilted sideways by 10-30 degrees
        pitch = -rng.uniform(0.0, 0.45) * vfov * D2R
        a = rng.choice([-1, 1]) * rng.uniform(10, 30) * D2R
        up = [round(math.sin(a) * math.cos(yaw), 5), round(math.cos(a), 5),
              round(math.sin(a) * math.sin(yaw), 5)]
    elif cam_kind == "grazing":  # the horizon near the top of the frame, water kilometres away
        pitch = -(0.5 * vfov - rng.uniform(1, 4)) * D2R
    else:  # glitter: towards the light's mirror image (as deep below the horizon as it is above)
        glitter_el = math.asin(rng.uniform(0.05, 0.2))
        pitch = -glitter_el + rng.uniform(-0.1, 0.1) * vfov * D2R
    if light_kind == "front_visible":
        pitch = -rng.uniform(-0.05, 0.15) * vfov * D2R
    fwd = direction(yaw, pitch)
    pos = [round(rng.uniform(-20, 20), 4), round(rng.uniform(1.5, 12), 4),
           round(rng.uniform(-20, 20), 4)]
    dist = rng.uniform(20, 80)
    look = [round(pos[c] + dist * fwd[c], 4) for c in range(3)]

    # Light: elevation and azimuth relative to the view; `direction` not of unit length.
    if light_kind == "front_low":
        el, az = math.asin(rng.uniform(0.05, 0.3)), rng.uniform(-0.15, 0.15)
    elif light_kind == "side":
        el, az = rng.uniform(8, 40) * D2R, rng.choice([-1, 1]) * rng.uniform(60, 110) * D2R
    elif light_kind == "behind":
        el, az = rng.uniform(10, 50) * D2R, math.pi + rng.uniform(-0.4, 0.4)
    elif light_kind == "overhead":
        el, az = rng.uniform(70, 89) * D2R, rng.uniform(-math.pi, math.pi)
    elif light_kind == "front_visible":  # in the frame, above the horizon
        el = max(pitch + rng.uniform(0.12, 0.38) * vfov * D2R, 3 * D2R)
        az = rng.uniform(-0.25, 0.25) * vfov * D2R
    else:
        el, az = glitter_el, rng.uniform(-0.1, 0.1)
    light_dir = [round(c * rng.uniform(0.5, 3), 6) for c in direction(yaw + az, el)]
    big = k % 4 == 2 or light_kind == "front_visible"
    radius = rng.uniform(1.5, 5.0) if big else rng.uniform(0.27, 1.2)
    # The light low in front over calm water: a glitter path of many pixels mirroring it.
    calm = light_kind in ("front_low", "front_visible", "glitter")
    if light_kind == "front_low" and k % 2 == 0:
        radius = rng.uniform(3, 8)
    if glitter:
        radius = rng.uniform(5, 15)

    fps = rng.choice([24, 30, 60])
    frames = rng.randint(2, 120)
    frame = 0 if k % 8 == 6 else rng.randint(1, frames - 1)
    t0 = round(rng.choice([0.0, rng.uniform(-3, 7)]), 5) if k % 5 else 0.0
    shutter = [0.0, 0.5, 1.0][k % 3]
    tf = t0 + frame / fps

    camera = {"up": up, "vfov_deg": round(vfov, 4)}
    if fmt == 3 and (moving or k % 9 != 0):
        # Keyframes: 2 or 3, 0.1-0.6 s apart, t_f before, between or after them.
        where = (moving or {}).get("where") or ["inside", "before", "after"][(k // 3) % 3]
        swing = (moving or {}).get("swing", 25)
        nkey, seg = rng.choice([2, 3]), rng.uniform(0.1, 0.6)
        start = {"before": tf + rng.uniform(0.05, 0.5),
                 "after": tf - nkey * seg - rng.uniform(0.05, 0.5),
                 "inside": tf - rng.uniform(0.2, 0.8) * (nkey - 1) * seg}[where]
        keys, p, la = [], list(pos), list(look)
        for n in range(nkey):
            keys.append({"time": round(start + n * seg, 6), "position": [round(c, 4) for c in p],
                         "look_at": [round(c, 4) for c in la]})
            p = [p[0] + rng.uniform(-4, 4), max(1.5, p[1] + rng.uniform(-1, 1)),
                 p[2] + rng.uniform(-4, 4)]
            la = [la[0] + rng.uniform(-swing, swing), la[1] + rng.uniform(-3, 3),
                  la[2] + rng.uniform(-swing, swing)]
        camera["keyframes"] = keys
        name += "_kf" + where + ("_moving" if moving else "")
    else:
        camera["position"], camera["look_at"] = pos, look

    scene = {"format": "sunglint-scene/%d" % fmt, "name": name,
             "image": {"width": width, "height": height}, "camera": camera,
             "light": {"direction": light_dir, "angular_radius_deg": round(radius, 5),
                       "radiance": (random_colour(rng, fmt, 1, 60) if fmt > 1
                                    else round(rng.choice([1.0, rng.uniform(1, 40)]), 4)),
                       "visible": (light_kind == "front_visible"
                                   or rng.random() < (0.6 if glitter else 0.3))}}
    if fmt == 1 or rng.random() < 0.3:
        scene["sky"] = {"radiance": random_colour(rng, fmt, 0, 0.6)}
    else:
        scene["sky"] = {"zenith": random_colour(rng, fmt, 0.02, 0.3),
                        "horizon": random_colour(rng, fmt, 0.2, 0.8)}
        if rng.random() < 0.7:
            scene["sky"]["exponent"] = round(rng.uniform(0.2, 3), 4)
    scene["surface"] = {"geometry": "displaced" if displaced else "flat",
                        # (a steep camera sees no horizon: without Fresnel, often one value)
                        "fresnel": ("schlick" if k % 2 == 0 or moving or cam_kind == "steep"
                                    else "none"),
                        "sea_radiance": (random_colour(rng, fmt, 0, 0.05) if rng.random() < 0.6
                                         else 0.0),
                        "waves": random_waves(rng, rng.randint(2, 8),
                                              (0.01, 0.06) if calm else (0.02, 0.3))}
    scene["animation"] = {"t0": t0, "fps": fps, "frames": frames, "shutter": shutter}
    # Every camera position above the crests.
    crest = sum(w["amplitude"] for w in scene["surface"]["waves"])
    for p in [kf["position"] for kf in camera.get("keyframes", [])] + [camera.get("position")]:
        if p is not None and p[1] < crest + 0.5:
            p[1] = round(crest + 0.5 + rng.uniform(0, 1), 4)
    return name, scene, frame


def scenes():
    rng = random.Random(SEED)
    out = [make_scene(k, rng) for k in range(34)]
    rng = random.Random(SEED + 1)  # /3 cameras moving (up to ~20 m/s) and turning fast
    for k, where, swing in [(34, "inside", 60), (35, "inside", 80), (36, "before", 40),
                            (37, "after", 40), (38, "inside", 60), (39, "inside", 30)]:
        out.append(make_scene(k, rng, {"where": where, "swing": swing}))
    rng = random.Random(SEED + 2)  # many pixels mirroring the light, in /1, /2 and /3
    out += [make_scene(k, rng, glitter=True) for k in (40, 41, 42, 43)]
    return out


# ---- the comparison ------------------------------------------------------------------------
def excluded_reason(notes):
    """Why a pixel is left out of the comparison (None: it is compared)."""
    if notes.unstable_hit:
        return "far or grazing hit"
    near = [(v, k) for k, v in notes.margins.items() if v < MARGIN]
    return min(near)[1] if near else None


def fmt3(v):
    return "(%s)" % ", ".join("%.7g" % c for c in v)


SEEN = ["sky", "light", "glint", "reflected sky", "sea"]


def check_scene(sunglint, outdir, name, scene, frame, total, failures):
    """Render one scene with sunglint and with spec_point, compare, print one line."""
    path = os.path.join(outdir, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
    out = os.path.join(outdir, name + ".point.pfm")
    cmd = [sunglint, "render", path, "-m", "point", "--frame", str(frame), "-o", out,
           "-j", "1", "-q"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        print("%-49s sunglint exited %d" % (name, run.returncode))
        failures.append("%s: sunglint exited %d: %s" % (name, run.returncode, run.stderr.strip()))
        return
    theirs = pfm.read_rows(out)
    sc = spec_point.Scene(scene)
    mine, notes = sc.render_point(frame)
    if len(theirs) != sc.height or len(theirs[0]) != sc.width:
        print("%-49s wrong size" % name)
        failures.append("%s: sunglint's image is %dx%d, the scene's %dx%d"
                        % (name, len(theirs[0]), len(theirs), sc.width, sc.height))
        return
    seen = dict.fromkeys(SEEN, 0)
    excluded = bad = 0
    max_abs = max_rel = 0.0
    for j in range(sc.height):
        for i in range(sc.width):
            note = notes[j][i]
            seen[note.seen] += 1
            total["seen"][note.seen] += 1
            total["pixels"] += 1
            a, b = theirs[j][i], mine[j][i]
            rel = max(abs(a[c] - b[c]) / max(1.0, abs(b[c])) for c in range(3))
            reason = excluded_reason(note)
            if reason:
                total["excluded_max_rel"] = max(total["excluded_max_rel"], rel)
                excluded += 1
                total["excluded"][reason] = total["excluded"].get(reason, 0) + 1
                continue
            total["compared"] += 1
            nearest = min(note.margins.items(), key=lambda kv: kv[1])
            if nearest[1] < total["nearest"][0]:
                total["nearest"] = (nearest[1], nearest[0], name, i, j)
            diff = max(abs(a[c] - b[c]) for c in range(3))
            max_abs, max_rel = max(max_abs, diff), max(max_rel, rel)
            if rel > TOLERANCE:
                bad += 1
                if bad <= 3:
                    failures.append("%s frame %d pixel (%d, %d) (row 0 at the top, %s): "
                                    "sunglint %s, spec %s, |diff| %.3g"
                                    % (name, frame, i, j, note.seen, fmt3(a), fmt3(b), diff))
    if bad:
        failures.append("    %s: %d pixels differ; rerun: %s" % (name, bad, " ".join(cmd)))
    total["max_abs"] = max(total["max_abs"], max_abs)
    total["max_rel"] = max(total["max_rel"], max_rel)
    print("%-49s F=%-3d %dx%d  %s  excluded %d  max|diff| %.1e (rel %.1e)  %s"
          % (name, frame, sc.width, sc.height, " ".join("%s %d" % (k, seen[k]) for k in SEEN),
             excluded, max_abs, max_rel, "%d DIFFER" % bad if bad else "ok"), flush=True)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sunglint, outdir = sys.argv[1], sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    start = time.time()
    cases = scenes()
    total = {"pixels": 0, "compared": 0, "excluded": {}, "max_abs": 0.0, "max_rel": 0.0,
             "seen": dict.fromkeys(SEEN, 0), "excluded_max_rel": 0.0,
             "nearest": (float("inf"), None, None, None, None)}
    failures = []
    for name, scene, frame in cases:
        check_scene(sunglint, outdir, name, scene, frame, total, failures)
    n_excl = sum(total["excluded"].values())
    print("total: %d scenes, %d pixels, %d compared, %d excluded (%s), "
          "max|diff| %.2e (relative %.2e), %.1f s"
          % (len(cases), total["pixels"], total["compared"], n_excl,
             ", ".join("%s %d" % kv for kv in sorted(total["excluded"].items())) or "none",
             total["max_abs"], total["max_rel"], time.time() - start))
    print("excluded pixels (not judged): largest relative difference %.2e"
          % total["excluded_max_rel"])
    print("pixels that see: %s" % ", ".join("%s %d" % (k, total["seen"][k]) for k in SEEN))
    print("the compared sample nearest a discontinuity: %.2g from the %s (%s, pixel (%s, %s))"
          % total["nearest"])
    if n_excl > MAX_EXCLUDED * total["pixels"]:
        failures.append("%d of %d pixels left out as near a discontinuity: more than %g%%"
                        % (n_excl, total["pixels"], 100 * MAX_EXCLUDED))
    if total["compared"] == 0:
        failures.append("no pixel compared")
    if failures:
        print("FAIL:\n" + "\n".join(failures))
        return 1
    print("PASS: sunglint's point images are the spec's, pixel for pixel")
    return 0


if __name__ == "__main__":
    sys.exit(main())
