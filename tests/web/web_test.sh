#!/usr/bin/env bash
# `sunglint web` end to end (docs/web.md): the page is written, self-contained and within its
# 2 MiB; the scene checks it carries give the CLI's message on every malformed scene
# (check_scenes.mjs); in headless Chromium on SwiftShader (check_web.mjs) the scripted frames
# equal `sunglint render --engine gl --display` of the same frame within 2/255 on 99.9% of
# the pixels (and 99% of the lit ones): on `simple` the split view (point | staa), staa,
# point and supersample 4x4x1 in one tab, on `sunset` (colour) point; a malformed scene
# dropped on the page shows the CLI's message; a bad parameter is named; a copy of the page
# broken on purpose (its exposure off by half a stop) fails the comparison; bad command
# lines are refused, naming the flag, and write nothing. The full set (the shared and the
# picture scenes; staa, point, the split view, staa-temporal, supersample) runs by hand:
# tests/web/web_full.sh, docs/web.md.
# Usage: web_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fails=0 passes=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
pass() { passes=$((passes + 1)); }
command -v node >/dev/null || { echo "FAIL node is not installed (Debian package nodejs)"; exit 1; }
chromium=${CHROMIUM:-/usr/bin/chromium}
[ -x "$chromium" ] || { echo "FAIL $chromium is not installed (Debian package chromium)"; exit 1; }
start=$SECONDS

# The page: two scenes (grey; colour with a visible sun), the shared scene first.
page=$work/page
if out=$("$bin" web "$src/scenes/simple.json" "$src/scenes/sunset.json" -o "$page" 2>&1); then
  pass
  grep -q "^web: $page/index.html (6 files, .* MiB; scenes simple, sunset)$" <<<"$out" && pass ||
    fail "web does not say what it wrote: $out"
else
  fail "web: $out"
fi
for f in index.html page.js host.js scene_check.js shaders.js data.js; do
  [ -s "$page/$f" ] && pass || fail "missing $page/$f"
done
bytes=$(cat "$page"/* | wc -c)
[ "$bytes" -le $((2 * 1024 * 1024)) ] && pass || fail "the page takes $bytes bytes, more than 2 MiB"
echo "page: $bytes bytes"
# Self-contained: nothing loaded from elsewhere (check_web.mjs also fails on any request
# that is not file: or data:).
if grep -qE '<(script|link|img)[^>]*(src|href)="(https?:)?//' "$page/index.html"; then
  fail "index.html loads something from the network"
else
  pass
fi

# Bad command lines: named, exit 2 (usage) or 1 (a bad scene), nothing written.
expect_refused() {
  local name=$1 code=$2 pattern=$3 out rc
  shift 3
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -ne "$code" ]; then fail "$name: exit $rc (wanted $code): $out"; return; fi
  grep -qF -- "$pattern" <<<"$out" && pass || fail "$name: wanted '$pattern', got: $out"
  [ -e "$work/refused" ] && fail "$name: wrote $work/refused" || pass
}
expect_refused "no scene" 2 "give at least one scene file" "$bin" web -o "$work/refused"
expect_refused "no folder" 2 "--out: give the page's folder" "$bin" web "$src/scenes/simple.json"
expect_refused "width" 2 "--width" "$bin" web "$src/scenes/simple.json" --width 0 -o "$work/refused"
expect_refused "bad scene" 1 "camera.position: must be above the water at rest" \
  "$bin" web "$src/scenes/simple.json" "$src/tests/scenes/bad/camera_low.json" -o "$work/refused"
expect_refused "same name" 1 "a second scene named 'simple'" \
  "$bin" web "$src/scenes/simple.json" "$src/scenes/simple.json" -o "$work/refused"

# The page's scene checks against the CLI's, on every malformed scene and more: in the
# background (the CLI's start-up is most of it), while Chromium compiles the kernel.
node "$src/tests/web/check_scenes.mjs" "$bin" "$src" "$work/scenes" >"$work/check_scenes.log" 2>&1 &
scenes_pid=$!

# The references: `render --engine gl` of frame 2 at 320x180, through the display pipeline
# (--display, PNG) and linear (PFM). simple: point catches the sun in a few pixels of frame
# 2 (none in frame 3).
frame=2 w=320 h=180
# ref SCENE NAME [--linear] FLAGS...: SCENE-NAME.png, and SCENE-NAME.pfm with --linear; a
# render that fails leaves a file that is no picture, so that the comparison fails at once.
ref() {
  local scene=$1 name=$2 linear=0 out
  shift 2
  [ "$1" = --linear ] && { linear=1; shift; }
  for out in "$work/$scene-$name.png" "$work/$scene-$name.pfm"; do
    [ "$out" = "$work/$scene-$name.pfm" ] && [ $linear -eq 0 ] && return
    local display=--display
    [ "${out##*.}" = pfm ] && display=
    # shellcheck disable=SC2086
    if ! "$bin" render "$src/scenes/$scene.json" "$@" --engine gl $display --width $w \
      --height $h --frame $frame -q -o "$out" >/dev/null; then
      fail "render $scene $* -o $out"
      echo "render failed" >"$out"
    fi
  done
}
# In the background, while Chromium compiles staa's shader (check_web.mjs waits for each
# file): one command after the other, each file written whole.
(
  ref simple point --linear -m point
  ref simple staa --linear -m staa
  ref simple supersample -m supersample --samples 4x4x1
  ref sunset point --linear -m point
  ref sunset staa --linear -m staa
) >"$work/references.log" 2>&1 &
refs_pid=$!
bad=syntax_error.json
cli_error=$(cd "$src/tests/scenes/bad" && "$bin" info "$bad" 2>&1)
json_string() { node -e 'console.log(JSON.stringify(process.argv[1]))' "$1"; }
png() { echo "\"compare\": [{\"ref\": \"$work/$1.png\", \"x0\": 0, \"x1\": $w}], \"lit_fraction\": 0.99"; }
pfm() { echo "\"linear\": {\"ref\": \"$work/$1.pfm\", \"max_relative_rmse\": $2}"; }
# One tab, the parameters changed by the fragment (no reload: the compiled kernel and the
# path table are kept): on simple (grey, dark: its glints are few, so the lit pixels are
# checked too, and counted) the split view, staa, point, supersample 4x4x1 (its jitter: the
# sampling streams on GLSL ES's emulated umulExtended); on sunset (colour, a visible sun, a
# gradient sky, Fresnel, 80 waves) staa and point; a malformed scene dropped (the CLI's
# message), then a valid one (loaded, shown); a bad parameter. The
# linear images' bounds are three or four times what SwiftShader measured against llvmpipe
# (docs/web.md: 4.3e-4, 8.8e-5 and 5.4e-5, the last one pixel's disk test flipped).
query="frame=$frame&width=$w&height=$h&paused=1&ui=0"
cat >"$work/jobs.json" <<JOBS
[{"name": "tab", "page": "$page/index.html", "width": $w, "height": $h,
  "query": "scene=simple&$query&method=point&split=staa",
  "steps": [
    {"compare": [{"ref": "$work/simple-point.png", "x0": 0, "x1": $((w / 2))},
                 {"ref": "$work/simple-staa.png", "x0": $((w / 2)), "x1": $w}],
     "lit_fraction": 0.99, "screenshot": "$work/simple-split.png"},
    {"hash": "method=staa&split=none", $(png simple-staa), "min_lit": 20, $(pfm simple-staa 1.5e-3)},
    {"hash": "method=point&split=none", $(png simple-point), "min_lit": 1, $(pfm simple-point 1e-3)},
    {"hash": "method=supersample-4x4x1&split=none", $(png simple-supersample), "min_lit": 8},
    {"hash": "scene=sunset&method=staa&split=none", $(png sunset-staa), "min_lit": 10000,
     $(pfm sunset-staa 3e-4)},
    {"hash": "scene=sunset&method=point&split=none", $(png sunset-point), "min_lit": 10000,
     $(pfm sunset-point 2e-4)},
    {"drop": "$src/tests/scenes/bad/$bad", "drop_name": "$bad", "expect": $(json_string "$cli_error")},
    {"drop": "$src/scenes/high.json", "drop_name": "high.json", "expect": "",
     "eval": "[sunglintPage.state.scenes[sunglintPage.state.scene].name, document.getElementById('scene').selectedOptions[0].text]",
     "eval_expect": ["high", "high (dropped)"]},
    {"hash": "method=nope", "error": "sunglint: method=nope: not one of point, supersample-2x2x1, supersample-4x4x1, staa-temporal, staa"}
  ]},
 {"name": "sunset", "page": "$page/index.html", "width": $w, "height": $h,
  "query": "scene=sunset&$query&method=point",
  "steps": [{$(png sunset-point), "min_lit": 10000}]}]
JOBS
# The tab; the sunset tab alone is for the broken copy below.
node -e 'const j = JSON.parse(require("fs").readFileSync(0, "utf8")); console.log(JSON.stringify([j[0]]))' \
  <"$work/jobs.json" >"$work/tab.json"
if out=$(timeout 600 node "$src/tests/web/check_web.mjs" "$work/tab.json" --chromium "$chromium" 2>&1); then
  pass
else
  fail "the page in Chromium: $out"
fi
echo "$out"
# The references' passes and failures (counted in the subshell, reported here).
wait $refs_pid
refs_failed=$(grep -c '^FAIL' "$work/references.log")
[ "$refs_failed" -eq 0 ] && pass || fail "references: $(cat "$work/references.log")"

# A copy broken on purpose: its exposure half a stop off must fail the comparison.
broken=$work/broken
cp -r "$page" "$broken"
sed -i 's/scale: 2 \*\* exposure/scale: 2 ** (exposure + 0.5)/' "$broken/host.js"
grep -q 'exposure + 0.5' "$broken/host.js" || fail "could not break the copy"
sed "s|$page/index.html|$broken/index.html|" "$work/jobs.json" |
  node -e 'const j = JSON.parse(require("fs").readFileSync(0, "utf8")); console.log(JSON.stringify([j[1]]))' \
    >"$work/broken.json"
if out=$(node "$src/tests/web/check_web.mjs" "$work/broken.json" --chromium "$chromium" 2>&1); then
  fail "a broken page passed: $out"
else
  grep -q "PROBLEM sunset: columns 0-$w: .* wanted 99.9%" <<<"$out" && pass || fail "broken page: $out"
fi

if wait $scenes_pid; then pass; else fail "scene checks: $(cat "$work/check_scenes.log")"; fi
tail -1 "$work/check_scenes.log"

echo "web_test: $passes passed, $fails failed in $((SECONDS - start)) s"
[ $fails -eq 0 ]
