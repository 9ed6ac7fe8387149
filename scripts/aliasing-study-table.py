#!/usr/bin/env python3
"""The aliasing study's tables (docs/aliasing-study.md) from the studies' results.json:
per scene, each variant's RMSE and temporal error over the image (the reference's noise
taken out) and the RMSE of the far half of the water, and `staa`'s ratios to `lean` and to
256-sample supersampling, the targets of docs/aliasing-study.md.
    python3 scripts/aliasing-study-table.py out/aliasing-study/results.json [...] > FILE
"""
import json
import math
import sys


def temporal_corrected(region):
    # The reference's frame-to-frame noise, 2 se^2, taken out as docs/report.md does for
    # the split's classes.
    t, se = region["temporal_error"], region["reference_se"]
    return math.sqrt(max(0.0, t * t - 2 * se * se))


def main(paths):
    for path in paths:
        d = json.load(open(path))
        s = d["settings"]
        print(f"### {s['width']}x{s['height']}, frames {s['frames'][0]}-{s['frames'][1]}, reference "
              f"`{s['reference']}` (`{path}`)\n")
        for scene in d["scenes"]:
            rows = {m["label"]: m["regions"] for m in scene["methods"]}
            se = rows["staa"]["image"]["reference_se"]
            print(f"**{scene['name']}** (reference's standard error {se:.1e}; far half "
                  f"{rows['staa']['far']['reference_se']:.1e})\n")
            print("| variant | RMSE | temporal error | far RMSE |")
            print("|---|---:|---:|---:|")
            for label, r in rows.items():
                print(f"| `{label}` | {r['image']['rmse_corrected']:.2e} | "
                      f"{temporal_corrected(r['image']):.2e} | {r['far']['rmse_corrected']:.2e} |")
            staa = rows["staa"]["image"]
            notes = []
            if "lean" in rows:
                lean = rows["lean"]["image"]
                notes.append(f"`staa` / `lean`: RMSE {staa['rmse_corrected'] / lean['rmse_corrected']:.2f}, "
                             f"temporal {temporal_corrected(staa) / temporal_corrected(lean):.2f} (target <= 0.7)")
            ss = [k for k in rows if k.startswith("supersample")]
            if ss:
                sup = rows[ss[0]]["image"]
                notes.append(f"/ `{ss[0]}`: RMSE {staa['rmse_corrected'] / sup['rmse_corrected']:.2f} "
                             "(target <= 1 on half the scenes)")
            if notes:
                print("\n" + "; ".join(notes) + ".")
            print()


if __name__ == "__main__":
    main(sys.argv[1:])
