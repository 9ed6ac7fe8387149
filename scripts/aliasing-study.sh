#!/usr/bin/env bash
# The aliasing study (docs/aliasing-study.md): where `staa` loses to `lean` and to 256-sample
# supersampling once most waves alias, each of its approximations swapped for a more exact
# counterpart in turn, on the four shared scenes and the aliasing scenes of
# tests/scenes/aliasing/ (make_aliasing_scenes.py). Writes out/aliasing-study{,-640}/ and
# regenerates docs/aliasing-study-160x90.md, docs/aliasing-study-640x360.md and
# docs/aliasing-study-tables.md (scripts/aliasing-study-table.py), and
# docs/aliasing-subpixel.md (scripts/aliasing-subpixel.py; needs ffmpeg).
#   bash scripts/aliasing-study.sh [build/sunglint]
# About 20 min on 2 cores with an empty cache (160x90: 7 scenes, frames 0-9, 32x32x1
# reference; 640x360: 5 scenes, frames 0-4, 12x12x1 reference; the elevation sweep, 5
# scenes at 160x90; then 7 min of sub-pixels);
# the frames are cached.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-$root/build/sunglint}
[ -x "$bin" ] || { echo "aliasing-study: $bin not found; build first (make build)" >&2; exit 1; }
cd "$root"
scenes=(scenes/simple.json scenes/smooth.json scenes/medium.json scenes/high.json
  tests/scenes/aliasing/cross-swell-side.json tests/scenes/aliasing/grazing-moon.json
  tests/scenes/aliasing/high-sun-above.json)
"$bin" compare "${scenes[@]}" \
  -m staa -m "staa --rdf-at centre" -m "staa --kernels 1" -m "staa --segments 4" \
  -m "staa --ndf per-pixel" -m "staa --elongation-threshold 1" \
  -m "staa --footprint none --rdf-at light --alias-start 0.3 --alias-end 0.8" \
  -m lean -m "supersample --samples 16x16x1" \
  --frames 0-9 --reference 32x32x1 --width 160 --height 90 --budgets none --no-video \
  --cache out/cache --out out/aliasing-study
"$bin" report out/aliasing-study/results.json --no-images \
  --title "The aliasing study at 160x90 (generated)" --markdown docs/aliasing-study-160x90.md
"$bin" compare "${scenes[@]:0:4}" tests/scenes/aliasing/grazing-moon.json \
  -m staa -m "staa --rdf-at centre" -m "staa --ndf per-pixel" -m lean \
  --frames 0-4 --reference 12x12x1 --width 640 --height 360 --budgets none --no-video \
  --cache out/cache --out out/aliasing-study-640
"$bin" report out/aliasing-study-640/results.json --no-images \
  --title "The aliasing study at 640x360 (generated)" --markdown docs/aliasing-study-640x360.md
# The light's elevation swept over one view (tests/scenes/aliasing/elevation-NN.json).
elevation=(tests/scenes/aliasing/elevation-{02,05,10,15,20}.json)
"$bin" compare "${elevation[@]}" -m staa -m lean -m "supersample --samples 16x16x1" \
  --frames 0-9 --reference 32x32x1 --width 160 --height 90 --budgets none --no-video \
  --cache out/cache --out out/aliasing-elevation
python3 scripts/aliasing-study-table.py out/aliasing-study/results.json \
  out/aliasing-study-640/results.json out/aliasing-elevation/results.json \
  > docs/aliasing-study-tables.md.tmp
mv docs/aliasing-study-tables.md.tmp docs/aliasing-study-tables.md
# The pixel's distribution of normals resolved by sub-pixels (docs/aliasing-study.md): each
# method at 2, 4 and 8 times the size, box-filtered down to 160x90, against the same
# reference frames (about 6 more minutes).
python3 scripts/aliasing-subpixel.py --bin "$bin" --cache out/cache --out out/aliasing-subpixel \
  > docs/aliasing-subpixel.md.tmp
python3 scripts/aliasing-subpixel.py --bin "$bin" --cache out/cache --out out/aliasing-subpixel \
  --section "The light's elevation" --scenes "$(IFS=,; echo "${elevation[*]}")" \
  --variants "staa|1,2,4;lean|1" >> docs/aliasing-subpixel.md.tmp
mv docs/aliasing-subpixel.md.tmp docs/aliasing-subpixel.md
