#!/usr/bin/env bash
# The demo: `sunglint compare` on the four shared scenes and the two spectrum oceans
# (scenes/ocean-wind.json, scenes/ocean-swell.json: 512 waves each) with every method of
# the catalogue, against a cached reference, and the report a user opens to see and trust
# the result (out/demo/index.html).
#
#   scripts/demo.sh [--full] [--docs] [path/to/sunglint]
#
# Default: 240x135, frames 0-9, reference 12x12x1, in out/demo (docs/report.md has the
# measured time; later runs take the frames from the cache). --full: the paper-sized
# study, 640x360, frames 0-29, reference 24x24x1, in out/demo-full (21 times the
# default's pixels x frames).
# --docs: then regenerate docs/results.md, docs/img/ and the README's demo section from
# the study's results.json (sunglint report).
#
# Methods: every catalogue method at its defaults, except `reference` (the ground truth
# column) and `supersample`, which appears as `supersample --samples 6x6x1` (the paper's
# MSAA-like baseline; the quality-cost curve covers its other budgets); `staa` appears
# three times: sunglint's default and the paper's method (`--footprint none`) with the
# uniform and the per-pixel NDF.
#
# Then a generated sea of four FFT cascades rendered by `staa` from the cascades' fields,
# a picture and a video in OUT/ocean-cascades/ (no reference: the sines number 65,536).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
full=0 docs=0 bin=$root/build/sunglint
for arg in "$@"; do
  case $arg in
    --full) full=1 ;;
    --docs) docs=1 ;;
    -h | --help) sed -n '2,17p' "$0"; exit 0 ;;
    *) bin=$arg ;;
  esac
done
[ -x "$bin" ] || { echo "demo: $bin not found; build first (make build)" >&2; exit 1; }

if [ $full -eq 1 ]; then
  out=out/demo-full size=(--width 640 --height 360) frames=0-29 reference=24x24x1
else
  out=out/demo size=(--width 240 --height 135) frames=0-9 reference=12x12x1
fi
methods=()
while read -r m; do
  case $m in
    reference) ;;
    supersample) methods+=(-m "supersample --samples 6x6x1") ;;
    staa)
      # sunglint's default (with the pixel-footprint term) and the paper's method with
      # either NDF (the rows of its Table 1).
      methods+=(-m "staa" -m "staa --footprint none --ndf uniform"
        -m "staa --footprint none --ndf per-pixel") ;;
    *) methods+=(-m "$m") ;;
  esac
done < <("$bin" compare --list-methods)

start=$(date +%s)
(cd "$root" && "$bin" compare scenes/simple.json scenes/smooth.json scenes/medium.json scenes/high.json \
  scenes/ocean-wind.json scenes/ocean-swell.json "${methods[@]}" "${size[@]}" --frames $frames \
  --reference "$reference" --cache out/cache --out "$out")
echo "demo: $(($(date +%s) - start)) s"
if [ $docs -eq 1 ]; then
  (cd "$root" && "$bin" report "$out/results.json" --markdown docs/results.md \
    --images docs/img --readme README.md)
fi
# A sea as engines make it: four 128 x 128 FFT cascades (65,536 lattice points, wind
# 10 m/s, the sea's look of `sunglint ocean`), `staa` reading the cascades' FFT fields
# (docs/ocean.md, "Shading from the cascades"): a picture and a video beside the study.
sea=$out/ocean-cascades
mkdir -p "$sea"
(cd "$root" && "$bin" ocean -o "$sea/sea.json" --cascades 4 --lattice 128 --wind-speed 10 --seed 1 \
  >/dev/null && "$bin" render "$sea/sea.json" -m staa "${size[@]}" --frame 0 --display -q \
  -o "$sea/staa.png" && "$bin" render "$sea/sea.json" -m staa "${size[@]}" --frames $frames -q \
  --video "$sea/staa.mp4")
echo "demo: a cascaded ocean, $root/$sea/staa.png and staa.mp4"
echo "demo: open $root/$out/index.html"
