#!/usr/bin/env bash
# The demo: renders the four shared scenes with `point` and `reference`, writes
# pictures, and prints the RMSE of point sampling against the reference.
# Usage: scripts/demo.sh [path/to/sunglint]
set -euo pipefail
bin=${1:-build/sunglint}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/out/demo
mkdir -p "$out"
printf '%-8s %-12s %s\n' scene "rmse(point)" "psnr(dB)"
for s in simple smooth medium high; do
  scene=$root/scenes/$s.json
  "$bin" render "$scene" -m reference -q --out "$out/${s}_reference.exr" >/dev/null
  "$bin" render "$scene" -m point -q --out "$out/${s}_point.exr" >/dev/null
  for m in reference point; do
    "$bin" render "$scene" -m $m -q --samples 2x2x2 --exposure 3 --out "$out/${s}_${m}.png" >/dev/null
  done
  "$bin" diff "$out/${s}_point.exr" "$out/${s}_reference.exr" --json --out "$out/${s}_diff.png" |
    python3 -c "import json,sys; d=json.load(sys.stdin); print('%-8s %-12.6f %.2f' % ('$s', d['rmse'], d['psnr']))"
done
echo "pictures and images in $out"
