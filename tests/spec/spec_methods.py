#!/usr/bin/env python3
"""Every method against the reference on the spec check's 44 seeded scenes
(spec_point_test.py: formats /1 to /3, flat and displaced, lights of 0.27 to 15 degrees in
front, beside, behind, overhead and in view, grazing, steep, rolled and moving cameras),
each at its own size and frame: one line a scene with the image's mean and each method's
RMSE against `reference --samples 16x16x1` (12x12x2 on displaced water; 4 batches; not
corrected for the reference's noise). What docs/targets.md ("The spec's random scenes")
states was measured with it; a study, not a test (about 10 minutes on two cores).

    python3 tests/spec/spec_methods.py build/sunglint out/spec-methods \
        [--methods "staa,supersample --samples 6x6x1,point"]

The references are kept in OUTDIR and reused. Standard library only.
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import pfm  # noqa: E402
import spec_point_test  # noqa: E402

METHODS = "staa,supersample --samples 6x6x1,point,lean,bruneton,specaa,staa-temporal"


def render(sunglint, args):
    r = subprocess.run([sunglint, "render"] + args + ["-q"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("sunglint render %s exited %d: %s" % (" ".join(args), r.returncode,
                                                      r.stderr.strip()))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sunglint")
    ap.add_argument("outdir")
    ap.add_argument("--methods", default=METHODS, help="comma-separated, each with its flags")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    methods = [m.split() for m in a.methods.split(",")]
    print("%-48s %9s  %s" % ("scene", "mean", "  ".join("%10s" % m[0][:10] for m in methods)))
    for name, scene, frame in spec_point_test.scenes():
        path = os.path.join(a.outdir, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        ref = os.path.join(a.outdir, name + ".ref.pfm")
        if not os.path.exists(ref):
            flat = scene["surface"]["geometry"] == "flat"
            render(a.sunglint, [path, "-m", "reference", "--samples",
                                "16x16x1" if flat else "12x12x2", "--batches", "4",
                                "--frame", str(frame), "-o", ref])
        r = pfm.read(ref)[3]
        errors = []
        for m in methods:
            out = os.path.join(a.outdir, name + "." + "_".join(m) + ".pfm")
            render(a.sunglint, [path, "-m"] + m + ["--frame", str(frame), "-o", out])
            x = pfm.read(out)[3]
            errors.append(math.sqrt(sum((p - q) ** 2 for p, q in zip(x, r)) / len(r)))
        print("%-48s %9.4g  %s" % (name, sum(r) / len(r),
                                   "  ".join("%10.3g" % e for e in errors)), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
