#!/usr/bin/env python3
"""Two results.json of one study, rendered differently (locally, or sharded into tasks and
merged), hold the same numbers: every value equal, except those measured with a clock (the
time per frame and what is derived from it: the equal-cost comparison at the same time)
and the counts of frames rendered and cached in each run, and the command.

Usage: same_results.py A.json B.json   (exit 0 when equal; prints the differences)
"""
import json
import sys

TIMED = {"ms_per_frame", "frames_rendered", "frames_cached", "command",
         "target_ms_per_frame", "same_cost", "cost_ratio"}


def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in TIMED}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v


def diff(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            diff(a.get(k), b.get(k), f"{path}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for k, (x, y) in enumerate(zip(a, b)):
            diff(x, y, f"{path}[{k}]", out)
    elif a != b:
        out.append(f"{path}: {a!r} != {b!r}")


a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
out = []
diff(a, b, "", out)
for line in out[:20]:
    print(line)
if out:
    print(f"{len(out)} differences")
sys.exit(1 if out else 0)
