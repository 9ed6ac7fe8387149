#!/usr/bin/env python3
"""`sunglint render -m reference` and `-m supersample` against the scene format's own
definition of a pixel's value, estimated by Monte Carlo from spec_point.py's radiance.

docs/scene-format.md defines a pixel's value as the mean of the radiance over the pixel's
square and over the frame's shutter interval [t_f - shutter / fps, t_f] (the camera at each
instant its own). This script estimates that mean independently of sunglint: B batches per
pixel, each of S x S spatial strata with one sample each, the instant Latin-hypercube
stratified over the interval, the radiance from spec_point.Scene (the reading written from
the spec's text alone). The batches' spread gives each pixel's variance of the mean. It then
holds against it:

- `reference` (--samples 8x8x1 on flat water, 8x8x4 on displaced, 8 batches, with its
  --variance-out), with --adaptive on and off: its estimate of the same mean;
- `supersample` 8x8x8 (8x8x4 on displaced) against the shutter's mean, and 8x8x1 against
  the mean at t_f alone (the spec: T = 1 samples the display time).

A scene passes when each channel's image mean is within Z_MEAN standard errors, the RMS
difference is at most MAX_RMS_RATIO times the RMS standard error, and at most
max(MAX_OUTLIERS, OUTLIER_SHARE of the pixels) pixels lie beyond Z_PIXEL standard errors (a
rare glint that one estimate drew and the other did not may be one). A pixel whose two
variances are both 0 (no light, no horizon in it) counts as one unless the two agree to
2e-6 relative. Supersample's own error is not measured; it is taken as that of one Monte
Carlo batch with as many spatial strata as it has positions (each a stratified estimate,
one sample a stratum), and since its fixed grid errs by more than that at a horizon or a
moving camera's edge, it is allowed an RMS ratio of 3 and 5% of its pixels beyond.

--plant FAULT puts a fault into the reading instead (the pixel grid moved by half a pixel,
`shift`; the interval [t_f, t_f + shutter / fps], `shutter`; the display time a frame late,
`frame`): the script then passes only when the comparison notices it, so the check is shown
able to fail. The scenes are spec_point_test.py's, seeded.

    python3 tests/spec/spec_mc.py build/sunglint out/spec-mc            # every scene, ~25 min
    python3 tests/spec/spec_mc.py build/sunglint out/spec-mc --quick    # the CTest's, ~10 s
    python3 tests/spec/spec_mc.py build/sunglint out/spec-mc --quick --plant shift

--scenes REGEX keeps the scenes whose names match. Exit 0 on a pass, 1 on a failure.
Standard library only.
"""
import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import pfm  # noqa: E402
import spec_point  # noqa: E402
import spec_point_test  # noqa: E402

Z_MEAN = 5.0          # an image mean's difference, in its standard errors
Z_PIXEL = 5.0         # a pixel's difference, in its standard errors
MAX_OUTLIERS = 3      # pixels beyond Z_PIXEL a scene may hold ...
OUTLIER_SHARE = 0.01  # ... or this share of its pixels, whichever is more (reference)
OUTLIER_SHARE_SUPERSAMPLE = 0.05  # supersample: its fixed grid's error at edges is not noise
MAX_RMS_RATIO = 2.0   # the RMS difference over the RMS standard error, whole image ...
MAX_RMS_RATIO_SUPERSAMPLE = 3.0  # ... and for supersample, whose error is only modelled
EXACT = 2e-6          # relative: pixels without variance on either side (float32 output)
# --quick: these scenes (the light in front, to the side, behind, overhead and in
# view; the three formats; shutters 0, 0.5 and 1; /3 cameras moving fast; the light low in
# front over calm water; one displaced), 12 pixels wide.
QUICK = ["s00_", "s02_", "s04_", "s06_", "s10_", "s13_", "s34_", "s35_", "s41_", "s42_"]
QUICK_WIDTH = 12


def render_mc(sc, frame, strata, batches, mode, plant, seed=1):
    """The pixel means by stratified Monte Carlo: mode "shutter" over the frame's interval,
    "tf" at the display time. Returns (mean, var): image[j][i] = (r, g, b), var the variance
    of each mean from the batches' spread."""
    tf = sc.display_time(frame + (1 if plant == "frame" else 0))
    length = sc.shutter / sc.fps
    t_start = tf + (0 if plant == "shutter" else -length)
    offset = 0.5 if plant == "shift" else 0.0
    n = strata * strata
    cameras = {} if len(sc.keys) > 1 else None
    still = sc.camera_at(tf) if cameras is None else None
    mean = [[None] * sc.width for _ in range(sc.height)]
    var = [[None] * sc.width for _ in range(sc.height)]
    for j in range(sc.height):
        for i in range(sc.width):
            rng = random.Random((seed * 1000003 + j) * 100003 + i)
            batch_means = []
            for _ in range(batches):
                order = list(range(n))
                rng.shuffle(order)
                acc = [0.0, 0.0, 0.0]
                for k in range(n):
                    x = i + offset + (k % strata + rng.random()) / strata
                    y = j + offset + (k // strata + rng.random()) / strata
                    t = tf if mode == "tf" else t_start + length * (order[k] + rng.random()) / n
                    cam = still if cameras is None else sc.camera_at(t)
                    o, d = sc.ray(cam, x, y)
                    value = sc.radiance(o, d, t)
                    for c in range(3):
                        acc[c] += value[c]
                batch_means.append([a / n for a in acc])
            m = [sum(b[c] for b in batch_means) / batches for c in range(3)]
            mean[j][i] = m
            var[j][i] = [sum((b[c] - m[c]) ** 2 for b in batch_means) / (batches * (batches - 1))
                         for c in range(3)]
    return mean, var


def compare(sc, theirs, their_var, mine, my_var, outlier_share=OUTLIER_SHARE,
            max_rms_ratio=MAX_RMS_RATIO):
    """(passed, one-line summary) of sunglint's image (and its variance, or None) against
    the Monte Carlo's."""
    w, h = sc.width, sc.height
    npx = w * h
    worst_mean_z, means = 0.0, []
    for c in range(3):
        d = sum(theirs[j][i][c] - mine[j][i][c] for j in range(h) for i in range(w)) / npx
        v = sum(my_var[j][i][c] + (their_var[j][i][c] if their_var else 0.0)
                for j in range(h) for i in range(w)) / npx ** 2
        means.append(sum(mine[j][i][c] for j in range(h) for i in range(w)) / npx)
        if v > 0:
            worst_mean_z = max(worst_mean_z, abs(d) / math.sqrt(v))
        elif abs(d) > EXACT * max(1.0, abs(means[-1])):
            worst_mean_z = math.inf
    outliers, exact_bad, sq, noise = [], [], 0.0, 0.0
    for j in range(h):
        for i in range(w):
            z = 0.0
            for c in range(3):
                d = theirs[j][i][c] - mine[j][i][c]
                v = my_var[j][i][c] + (their_var[j][i][c] if their_var else 0.0)
                sq += d * d
                noise += v
                scale = max(1.0, abs(mine[j][i][c]))
                if v <= 1e-24:  # neither estimate varies: equal, or a glint one of them missed
                    if abs(d) > EXACT * scale:
                        exact_bad.append((i, j))
                        z = math.inf
                    continue
                z = max(z, abs(d) / math.sqrt(v + (0.5 * EXACT * scale) ** 2))
            if z > Z_PIXEL:
                outliers.append((z, i, j))
    allowed = max(MAX_OUTLIERS, int(outlier_share * npx))
    rms_ratio = math.sqrt(sq / max(noise, 1e-300))
    passed = worst_mean_z <= Z_MEAN and len(outliers) <= allowed and rms_ratio <= max_rms_ratio
    outliers.sort(reverse=True)
    line = ("mean %.4g  mean z %.2f  RMS diff / noise %.2f  beyond %g se: %d (of %d allowed)%s%s"
            % (sum(means) / 3, worst_mean_z, rms_ratio, Z_PIXEL,
               len(outliers), allowed,
               "  worst (%d, %d) z %.1f" % (outliers[0][1], outliers[0][2], outliers[0][0])
               if outliers else "",
               "  (%d of them without variance)" % len(exact_bad) if exact_bad else ""))
    return passed, line


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("%s exited %d: %s" % (" ".join(cmd), r.returncode, r.stderr.strip()))


def check_scene(sunglint, outdir, name, scene, frame, plant, strata, batches):
    """Every comparison of one scene: a list of (passed, label, summary)."""
    path = os.path.join(outdir, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
    sc = spec_point.Scene(scene)
    base = [sunglint, "render", path, "--frame", str(frame), "-j", "1", "-q"]
    results = []
    mc = {}
    for mode in ("shutter", "tf"):
        mc[mode] = render_mc(sc, frame, strata, batches, mode, plant)
    out, var = os.path.join(outdir, name + ".ref.pfm"), os.path.join(outdir, name + ".var.pfm")
    for adaptive in ("on", "off"):
        run(base + ["-m", "reference", "-o", out, "--variance-out", var, "--batches", "8",
                    "--samples", "8x8x4" if sc.displaced else "8x8x1", "--adaptive", adaptive])
        results.append(("reference, adaptive " + adaptive,)
                       + compare(sc, pfm.read_rows(out), pfm.read_rows(var), *mc["shutter"]))
    for samples, mode in (("8x8x4" if sc.displaced else "8x8x8", "shutter"), ("8x8x1", "tf")):
        out = os.path.join(outdir, name + ".ss" + samples + ".pfm")
        run(base + ["-m", "supersample", "-o", out, "--samples", samples])
        # Supersample's own error, unknown, taken as one Monte Carlo batch's scaled to its
        # positions: S x S strata of one sample each either way (its instants stratified too).
        positions = int(samples.split("x")[0]) ** 2
        scale = batches * strata * strata / positions
        mine, my_var = mc[mode]
        ss_var = [[[v * scale for v in px] for px in row] for row in my_var]
        results.append(("supersample %s / %s" % (samples, "shutter" if mode == "shutter"
                                                  else "t_f"),)
                       + compare(sc, pfm.read_rows(out), ss_var, mine, my_var,
                                 OUTLIER_SHARE_SUPERSAMPLE, MAX_RMS_RATIO_SUPERSAMPLE))
    return [(ok, label, line) for label, ok, line in results]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sunglint")
    ap.add_argument("outdir")
    ap.add_argument("--quick", action="store_true",
                    help="the CTest's nine flat scenes, %d pixels wide" % QUICK_WIDTH)
    ap.add_argument("--scenes", default="", help="a regular expression on the scenes' names")
    ap.add_argument("--plant", choices=["none", "shift", "shutter", "frame"], default="none")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    strata, batches = 8, 8
    cases = spec_point_test.scenes()
    if a.quick:
        cases = [c for c in cases if any(c[0].startswith(q) for q in QUICK)]
        for _, scene, _ in cases:
            im = scene["image"]
            im["height"] = max(1, round(im["height"] * QUICK_WIDTH / im["width"]))
            im["width"] = QUICK_WIDTH
    if a.scenes:
        cases = [c for c in cases if re.search(a.scenes, c[0])]
    if not cases:
        sys.exit("no scene matches --scenes %r" % a.scenes)
    start, failed = time.time(), []
    for name, scene, frame in cases:
        try:
            results = check_scene(a.sunglint, a.outdir, name, scene, frame, a.plant, strata,
                                  batches)
        except (RuntimeError, ValueError) as e:
            print("%s: %s" % (name, e))
            failed.append(name)
            continue
        for ok, label, line in results:
            print("%-44s %-30s %s  %s" % (name, label, line, "ok" if ok else "DIFFERS"),
                  flush=True)
            if not ok:
                failed.append("%s (%s)" % (name, label))
    print("%d scenes, %d comparisons failed, %.1f s (Monte Carlo %d x %d strata x %d batches a "
          "pixel)" % (len(cases), len(failed), time.time() - start, strata, strata, batches))
    if a.plant != "none":
        if failed:
            print("PASS: the planted fault (%s) was noticed in %d comparisons"
                  % (a.plant, len(failed)))
            return 0
        print("FAIL: the planted fault (%s) went unnoticed" % a.plant)
        return 1
    if failed:
        print("FAIL:\n  " + "\n  ".join(failed))
        return 1
    print("PASS: reference and supersample are the spec's pixel means within their noise")
    return 0


if __name__ == "__main__":
    sys.exit(main())
