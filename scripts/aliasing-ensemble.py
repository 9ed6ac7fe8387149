#!/usr/bin/env python3
"""How much of a method's error a better distribution of normals could remove at all.

For each scene, the waves' phases are drawn afresh N times (uniform, independent: the
ensemble that Eq. 3's Gaussian, and any model of the aliasing waves' normals beyond it such
as the product of J0 factors, describe), and frame 0 is rendered at 160x90 by each method
and by the reference. Per pixel p, the method's error d_i(p) against the reference over the
draws i splits into

  bias^2(p)        = (mean_i d_i(p))^2 - var_i(d(p)) / N     (unbiased for the squared mean)
  realization(p)   = var_i(d(p)) - the reference's own noise variance at p

With every phase drawn, the bias is a lower bound on what a model of the aliasing waves'
ensemble could remove: the method's resolved part follows the resolved waves' phases, and
its error given them may average out only over them. With --hold F the longer fraction F
of the waves (by wavelength) keeps the scene's phases and the shorter ones alone are
drawn: the bias is then the error given the long waves, which holds the ensemble model's
whole error wherever the short waves alias and the long ones are resolved (and the long
waves' own arrangement where they alias too: an upper estimate there).

The bias is what survives averaging over the phases: every error of the method's model of
the ensemble (the Gaussian's shape, the RDF's linearisation, the footprint term) sits there,
so its share bounds from above what any ensemble distribution could remove. The
realization term is the pixel's own arrangement of its phases, which no distribution of
normals follows (docs/aliasing-study.md, "What the Gaussian costs").

Usage: scripts/aliasing-ensemble.py SUNGLINT OUT_DIR [--draws N] [--samples SxSxT] [--hold F]
Writes OUT_DIR/aliasing-ensemble.md (the table) and keeps the frames in OUT_DIR.
Regenerates docs/aliasing-study.md's table "Bias against realization".
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pfm  # noqa: E402

SCENES = [
    ("simple", "scenes/simple.json"),
    ("smooth", "scenes/smooth.json"),
    ("medium", "scenes/medium.json"),
    ("high", "scenes/high.json"),
    ("cross-swell", "tests/scenes/aliasing/cross-swell-side.json"),
    ("grazing moon", "tests/scenes/aliasing/grazing-moon.json"),
    ("high sun", "tests/scenes/aliasing/high-sun-above.json"),
]
METHODS = ["staa", "lean"]
WIDTH, HEIGHT = 160, 90


def read_pfm(path):
    """The first channel of a PFM image, as a flat list (the scenes are grey)."""
    try:
        _, _, channels, values = pfm.read(path)
    except ValueError as e:
        sys.exit(str(e))
    return values[::channels]


def render(sunglint, scene, method, out, extra):
    cmd = [sunglint, "render", scene, "--method", method, "--frame", "0",
           "--width", str(WIDTH), "--height", str(HEIGHT), "-o", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed:\n{r.stderr}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sunglint")
    ap.add_argument("out")
    ap.add_argument("--draws", type=int, default=16)
    ap.add_argument("--samples", default="16x16x1")
    ap.add_argument("--hold", type=float, default=0.0)
    a = ap.parse_args()
    if not 0.0 <= a.hold < 1.0:
        sys.exit("--hold: a fraction of the waves in [0, 1)")
    if a.draws < 2:
        sys.exit("--draws: at least 2 (the split needs a variance)")
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for name, path in SCENES:
        scene = json.load(open(path))
        waves = scene["surface"]["waves"]
        # The shorter waves, drawn; the longer fraction `hold` keeps its phases.
        by_length = sorted(waves, key=lambda w: math.hypot(*w["wave_vector"]))
        drawn_waves = by_length[: len(waves) - int(a.hold * len(waves))]
        diffs = {m: [] for m in METHODS}
        noise = None
        for i in range(a.draws):
            rng = random.Random(f"{name}/{i}")
            for w in drawn_waves:
                w["phase"] = rng.uniform(0.0, 2.0 * math.pi)
            tag = f"{name.replace(' ', '-')}-{i:02d}"
            drawn = os.path.join(a.out, tag + ".json")
            with open(drawn, "w") as f:
                json.dump(scene, f)
            ref, var = (os.path.join(a.out, tag + s) for s in ("-ref.pfm", "-var.pfm"))
            render(a.sunglint, drawn, "reference", ref,
                   ["--samples", a.samples, "--variance-out", var])
            r, v = read_pfm(ref), read_pfm(var)
            noise = v if noise is None else [x + y for x, y in zip(noise, v)]
            for m in METHODS:
                out = os.path.join(a.out, f"{tag}-{m}.pfm")
                render(a.sunglint, drawn, m, out, [])
                diffs[m].append([x - y for x, y in zip(read_pfm(out), r)])
            print(f"{name}: draw {i + 1} of {a.draws}", file=sys.stderr, flush=True)
        n = a.draws
        pixels = len(noise)
        noise_var = sum(noise) / (n * pixels)  # the reference's mean variance a pixel
        row = {"scene": name, "ref_se": math.sqrt(noise_var)}
        for m in METHODS:
            d = diffs[m]
            mse = bias2 = 0.0
            for p in range(pixels):
                col = [d[i][p] for i in range(n)]
                mean = sum(col) / n
                var = sum((x - mean) ** 2 for x in col) / (n - 1)
                mse += sum(x * x for x in col) / n
                bias2 += mean * mean - var / n
            mse = mse / pixels - noise_var
            bias2 /= pixels
            row[m] = (math.sqrt(max(mse, 0.0)), math.sqrt(max(bias2, 0.0)),
                      max(bias2, 0.0) / mse if mse > 0 else float("nan"))
        rows.append(row)
    lines = [
        f"RMSE at {WIDTH}x{HEIGHT}, frame 0, over {a.draws} draws of the "
        + (f"phases of the shorter {1 - a.hold:.0%} of the waves " if a.hold > 0 else
           "waves' phases ")
        + f"(reference `{a.samples}`, its noise taken out), and the part of it that "
        "survives averaging over the draws (the bias):",
        "",
        "| scene | reference's se | `staa` RMSE | `staa` bias | bias's share of `staa`'s MSE "
        "| `lean` RMSE | `lean` bias | bias's share of `lean`'s MSE |",
        "|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        s, l = r["staa"], r["lean"]
        lines.append(
            f"| {r['scene']} | {r['ref_se']:.1e} | {s[0]:.2e} | {s[1]:.2e} | {s[2]:.2f} "
            f"| {l[0]:.2e} | {l[1]:.2e} | {l[2]:.2f} |")
    text = "\n".join(lines) + "\n"
    target = os.path.join(a.out, "aliasing-ensemble.md")
    with open(target + ".tmp", "w") as f:
        f.write(text)
    os.replace(target + ".tmp", target)
    print(text)


if __name__ == "__main__":
    main()
