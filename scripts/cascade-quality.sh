#!/usr/bin/env bash
# The quality of the methods on generated cascade seas (docs/ocean.md, "Quality on
# generated cascade seas"): three seas of two 32 x 32 lattice cascades (940 lattice sines
# each, small enough for a reference on the exact sines), each under its own sun and
# camera, rendered by `point`, `supersample --samples 6x6x1`, `staa` (the cascades from
# their FFT fields) and `staa --cascades waves` (their sines) against a reference on the
# sines, with `sunglint compare`.
#
#   scripts/cascade-quality.sh [OUT] [WIDTH] [FRAMES] [REFERENCE] [GEOMETRY] [SEAS]
#   (defaults: out/cascade-quality 160 0-9 12x12x1 flat "wind5 wind10 wind15"; 640 0-4
#   12x12x1 for the larger study; the displaced measurement of docs/ocean.md:
#   `scripts/cascade-quality.sh out/cq-displaced 160 0-9 8x8x1 displaced wind10`)
#
# Each sea: `ocean --cascades 2 --lattice 32 --patch-sizes A,B --wind-speed W --seed 3`
# on a copy of scripts/templates/plain.json with the light E degrees high ahead and the
# camera 2.5 m up looking D degrees down:
#   wind5   W 5,  patches 8, 4 m,   E 3,  D 2.4 (the template's view)
#   wind10  W 10, patches 16, 8 m,  E 15, D 10
#   wind15  W 15, patches 24, 12 m, E 40, D 37
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$root/build/sunglint"
out="${1:-$root/out/cascade-quality}"
width="${2:-160}"
frames="${3:-0-9}"
reference="${4:-12x12x1}"
geometry="${5:-flat}"
seas="${6:-wind5 wind10 wind15}"
[ -x "$bin" ] || { echo "cascade-quality: build first (make build)" >&2; exit 1; }
mkdir -p "$out/scenes"

sea() {  # name wind patches sun_deg down_deg
  local name=$1 wind=$2 patches=$3 sun=$4 down=$5
  local t="$out/scenes/$name-template.json"
  awk -v e="$sun" -v d="$down" 'BEGIN { pi = atan2(0, -1) }
    /"direction":/ { printf "  \"direction\": [0.0, %.6f, %.6f],\n", sin(e*pi/180), -cos(e*pi/180); next }
    /"look_at":/ { printf "  \"look_at\": [0, 0, %.6f],\n", -2.5 / (sin(d*pi/180)/cos(d*pi/180)); next }
    { print }' "$root/scripts/templates/plain.json" >"$t"
  "$bin" ocean -o "$out/scenes/$name.json" --cascades 2 --lattice 32 --patch-sizes "$patches" \
    --wind-speed "$wind" --seed 3 --template "$t" --geometry "$geometry" >/dev/null
}
sea wind5 5 8,4 3 2.385944
sea wind10 10 16,8 15 10
sea wind15 15 24,12 40 37

files=()
for name in $seas; do files+=("$out/scenes/$name.json"); done
"$bin" compare "${files[@]}" \
  -m point -m 'supersample --samples 6x6x1' -m staa -m 'staa --cascades waves' \
  --width "$width" --frames "$frames" --reference "$reference" --budgets none --no-video \
  -o "$out/study-$width" --cache "$out/cache"
echo "cascade-quality: $out/study-$width"
