#!/usr/bin/env python3
"""The aliasing study's resolved-pixel counterpart (docs/aliasing-study.md, "What the
Gaussian costs: the pixel's normals resolved by sub-pixels"): each method rendered on a grid S times finer per axis
and box-filtered down to the study's 160x90, so that each 160x90 pixel's distribution of
normals is carried by S x S sub-pixels instead of the method's pixel-scale model (for
`staa`: one Gaussian for the aliasing waves and the footprint term; for `lean`: one
Gaussian for all the slopes). Measured against the study's own reference frames, read from
the compare cache (both batches: their mean is the reference, their spread its noise), with
the reference's noise taken out as scripts/aliasing-study-table.py does. (The study's
scenes are grey; a colour frame would be compared in its channels' mean.)

    python3 scripts/aliasing-subpixel.py [--bin build/sunglint] [--cache out/cache]
        [--out out/aliasing-subpixel] [--variants 'staa|1,2;lean|1']
        [--scenes A.json,B.json] [--section TITLE] > FILE

Needs the study's 160x90 reference in the cache (bash scripts/aliasing-study.sh) and ffmpeg
(it reads the cache's OpenEXR frames). About 6 minutes on 2 cores (the frames of each
variant kept in --out).
"""
import argparse
import glob
import json
import math
import os
import re
import shlex
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pfm  # noqa: E402

SCENES = ["scenes/simple.json", "scenes/smooth.json", "scenes/medium.json", "scenes/high.json",
          "tests/scenes/aliasing/cross-swell-side.json", "tests/scenes/aliasing/grazing-moon.json",
          "tests/scenes/aliasing/high-sun-above.json"]
# The study's variants: staa and lean resolved by finer grids; staa with the pixel's own
# aliasing band on every sub-pixel, and that band moved up by factors of 2.
DEFAULT_VARIANTS = ("staa|1,2,4,8;lean|1,2,4,8;staa@0.3-0.8|2,4,8;staa@0.6-1.6|4,8;"
                    "staa@1.2-3.2|8")
WIDTH, HEIGHT, FRAMES, REFERENCE = 160, 90, range(0, 10), "reference --samples 32x32x1"


def box_down(img, s):
    w, h, ch, v = img
    W, H = w // s, h // s
    out = [0.0] * (W * H * ch)
    inv = 1.0 / (s * s)
    for y in range(h):
        Y = y // s
        row = y * w * ch
        for x in range(w):
            X = x // s
            for c in range(ch):
                out[(Y * W + X) * ch + c] += v[row + x * ch + c] * inv
    return W, H, ch, out


def grey(img):
    w, h, ch, v = img
    return v if ch == 1 else [(v[3 * i] + v[3 * i + 1] + v[3 * i + 2]) / 3.0 for i in range(w * h)]


def reference_frames(cache, name, out):
    """{frame: [batch images]} of the study's reference for scene `name` at 160x90: the
    frames of the renderer version written last (a cache may hold older versions' too)."""
    by_renderer = {}
    for j in glob.glob(os.path.join(cache, "reference-samples-32x32x1-*.exr.json")):
        key = json.load(open(j))["key"]
        if f"\nsize={WIDTH}x{HEIGHT}\n" not in key or f'"name": "{name}"' not in key:
            continue
        if f"\nmethod={REFERENCE}\n" not in key:
            continue
        renderer = re.search(r"\nrenderer=(\S+)", key).group(1)
        by_renderer.setdefault(renderer, []).append((j, key))
    if not by_renderer:
        return {}
    newest = max(by_renderer.values(), key=lambda v: max(os.path.getmtime(j) for j, _ in v))
    found = {}
    for j, key in newest:
        frame = int(re.search(r"\nframe=(\d+)", key).group(1))
        image = os.path.join(out, "ref-" + os.path.basename(j)[:-len(".exr.json")] + ".pfm")
        if not os.path.exists(image):
            # The format stores rows bottom to top; ffmpeg writes them as they come.
            subprocess.run(["ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-i",
                            j[:-len(".json")], "-vf", "vflip", "-c:v", "pfm", "-f", "image2",
                            image], check=True)
        found.setdefault(frame, []).append(grey(pfm.read(image)))
    return found


def metrics(frames, ref, noise):
    """RMSE and temporal error over the frames, the reference's noise taken out."""
    n = len(frames[0])
    se2 = sum(noise) / len(noise)
    sq = sum((a - b) ** 2 for f in FRAMES for a, b in zip(frames[f], ref[f])) / (n * len(FRAMES))
    tq = 0.0
    for f in list(FRAMES)[1:]:
        tq += sum(((a1 - a0) - (b1 - b0)) ** 2 for a1, a0, b1, b0 in
                  zip(frames[f], frames[f - 1], ref[f], ref[f - 1]))
    tq /= n * (len(FRAMES) - 1)
    return math.sqrt(max(0.0, sq - se2)), math.sqrt(max(0.0, tq - 2 * se2)), math.sqrt(se2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/sunglint")
    ap.add_argument("--cache", default="out/cache")
    ap.add_argument("--out", default="out/aliasing-subpixel")
    ap.add_argument("--section", help="print a '## SECTION' heading instead of the page's "
                    "title (a second table appended to the same page)")
    ap.add_argument("--scenes", default=",".join(SCENES),
                    help="comma-separated scene files (their 160x90 reference in --cache)")
    ap.add_argument("--variants", default=DEFAULT_VARIANTS,
                    help="';'-separated METHOD|S,S,...: a method and its flags, or staa@A-B "
                    "(see below), and the scales S to render it at")
    a = ap.parse_args()
    variants = []
    for item in a.variants.split(";"):
        method, scales = item.split("|")
        variants += [(method, int(s)) for s in scales.split(",")]
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for scene in a.scenes.split(","):
        name = json.load(open(scene))["name"]
        ref_batches = reference_frames(a.cache, name, a.out)
        if sorted(ref_batches) != list(FRAMES) or any(len(b) < 2 for b in ref_batches.values()):
            sys.exit(f"aliasing-subpixel: the 160x90 reference of {name} is not in {a.cache}; "
                     "run bash scripts/aliasing-study.sh first")
        ref = {f: [sum(p) / len(p) for p in zip(*ref_batches[f])] for f in FRAMES}
        # Per pixel, the variance of the batches' mean: (b0 - b1)^2 / 4 for two batches.
        noise = []
        for f in FRAMES:
            b = ref_batches[f]
            k = len(b)
            for p in zip(*b):
                m = sum(p) / k
                noise.append(sum((x - m) ** 2 for x in p) / (k - 1) / k)
        for method, s in variants:
            tag = f"{name}-{method.replace(' ', '_')}-x{s}"
            pattern = os.path.join(a.out, tag + "-%04d.pfm")
            # "staa@A-B": staa whose aliasing band (Eq. 20) is A to B cycles per 160x90
            # pixel on every sub-pixel (A / S to B / S cycles per sub-pixel): the waves
            # below it resolved by the sub-pixels, those above it one Gaussian as the
            # pixel would have them ("staa@0.3-0.8": the pixel's own aliasing set).
            cmd = method
            band = re.fullmatch(r"staa@([0-9.]+)-([0-9.]+)", method)
            if band:
                lo, hi = float(band.group(1)), float(band.group(2))
                cmd = f"staa --alias-start {lo / s:g} --alias-end {hi / s:g}"
            subprocess.run([a.bin, "render", scene, "-m"] + shlex.split(cmd) + ["--frames",
                            f"{FRAMES[0]}-{FRAMES[-1]}", "--width", str(WIDTH * s), "--height",
                            str(HEIGHT * s), "-o", pattern, "-q"], check=True,
                           stdout=subprocess.DEVNULL)
            frames = {f: grey(box_down(pfm.read(pattern % f), s)) for f in FRAMES}
            r, t, se = metrics(frames, ref, noise)
            rows.append((name, method, s, r, t, se))
            print(f"aliasing-subpixel: {name} {method} x{s}: RMSE {r:.3e} temporal {t:.3e}",
                  file=sys.stderr)
    if a.section:
        print(f"## {a.section}\n")
    else:
        print("# The aliasing study: the pixel's normals resolved by sub-pixels (generated)\n")
        print("`bash scripts/aliasing-study.sh` runs `scripts/aliasing-subpixel.py` "
              "(docs/aliasing-study.md says what it measures).\n")
    print(f"At {WIDTH}x{HEIGHT}, frames {FRAMES[0]}-{FRAMES[-1]}, against the `{REFERENCE}` "
          "reference (the reference's noise taken out); each variant rendered at S times the "
          "size per axis and box-filtered down (S = 1: as the study renders it). "
          "`staa@A-B`: the aliasing band A to B cycles per 160x90 pixel on every sub-pixel.\n")
    variants = list(dict.fromkeys((r[1], r[2]) for r in rows))
    for title, col in (("RMSE", 3), ("temporal error", 4)):
        print(f"{title}:\n")
        print("| scene | reference's se | " + " | ".join(f"`{m}` S={s}" for m, s in variants) + " |")
        print("|---|---:|" + "---:|" * len(variants))
        for scene in dict.fromkeys(r[0] for r in rows):
            by = {(r[1], r[2]): r for r in rows if r[0] == scene}
            se = next(iter(by.values()))[5]
            print(f"| {scene} | {se:.1e} | " +
                  " | ".join(f"{by[v][col]:.2e}" for v in variants) + " |")
        print()


if __name__ == "__main__":
    main()
