#!/usr/bin/env bash
# The web page's full comparison, run by hand (docs/web.md records its output): on each
# scene, one Chromium tab (SwiftShader) draws frame FRAME at 320x180 in the split view
# (point | staa), then staa, point, staa-temporal and supersample 4x4x1 (the fragment
# changes the method: no reload), each against `sunglint render --engine gl --display` of
# that frame (within 2/255 on 99.9% of the pixels and on 99% of the lit ones), then times
# point and staa in the page (the median of BENCH renders each, GPU timer queries). Takes
# about a minute a scene here (most of it SwiftShader compiling staa's shader).
# Usage: web_full.sh SUNGLINT SOURCE_DIR WORK_DIR [SCENE.json...]   (default: the shared
# scenes simple, smooth, medium, high and the picture scenes sunset, moonlit, midday)
# Environment: FRAME (2), BENCH (3).
set -u
bin=$1 src=$2 work=$3
shift 3
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(simple smooth medium high sunset moonlit midday)
frame=${FRAME:-2} bench=${BENCH:-3} w=320 h=180
rm -rf "$work" && mkdir -p "$work"
paths=()
for s in "${scenes[@]}"; do paths+=("$src/scenes/${s%.json}.json"); done
"$bin" web "${paths[@]}" -o "$work/page" || exit 1
methods=(point staa staa-temporal "supersample --samples 4x4x1")
ids=(point staa staa-temporal supersample-4x4x1)
echo "["  >"$work/jobs.json"
first=1
for s in "${scenes[@]}"; do
  s=${s%.json}
  for k in "${!methods[@]}"; do
    # shellcheck disable=SC2086
    "$bin" render "$src/scenes/$s.json" -m ${methods[$k]} --engine gl --display --width $w \
      --height $h --frame "$frame" -q -o "$work/$s-${ids[$k]}.png" || exit 1
  done
  cmp() { echo "\"compare\": [{\"ref\": \"$work/$s-$1.png\", \"x0\": 0, \"x1\": $w}], \"lit_fraction\": 0.99"; }
  [ $first -eq 1 ] || echo "," >>"$work/jobs.json"
  first=0
  cat >>"$work/jobs.json" <<EOF
{"name": "$s", "page": "$work/page/index.html", "width": $w, "height": $h,
 "query": "scene=$s&frame=$frame&width=$w&height=$h&paused=1&ui=0&method=point&split=staa",
 "steps": [
  {"compare": [{"ref": "$work/$s-point.png", "x0": 0, "x1": $((w / 2))},
               {"ref": "$work/$s-staa.png", "x0": $((w / 2)), "x1": $w}], "lit_fraction": 0.99,
   "bench": $bench, "eval": "window.sunglintPage.renderer.tablesMs"},
  {"hash": "method=staa&split=none", $(cmp staa), "screenshot": "$work/$s-staa-page.png"},
  {"hash": "method=point&split=none", $(cmp point)},
  {"hash": "method=staa-temporal&split=none", $(cmp staa-temporal)},
  {"hash": "method=supersample-4x4x1&split=none", $(cmp supersample-4x4x1)}
 ]}
EOF
done
echo "]" >>"$work/jobs.json"
node "$src/tests/web/check_web.mjs" "$work/jobs.json" --timeout 3600
