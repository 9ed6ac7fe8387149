#!/usr/bin/env bash
# The study as a user meets it: `sunglint compare` on two shared scenes and a colour one at
# a tiny size writes a report that opens in headless Chromium with no console error, a
# summary of every scene first, every picture and video decoded (each video at least 3 s),
# every chart drawn (the flicker plot of each scene among them) with its methods told apart,
# its time axes logarithmic and its labels apart, and the crops shown at 2:1 pixels, never
# shrunk (check_page.mjs, which also saves a screenshot); a copy broken on purpose (a
# missing picture, a missing video, a script error, no summary, one colour for every
# method, a linear time axis, packed labels, a short video) is caught; bad options fail
# naming the option; without ffmpeg the error says what to do.
# Usage: report_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fails=0 passes=0
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
pass() { passes=$((passes + 1)); }

if ! command -v node >/dev/null; then
  echo "FAIL node is not installed (Debian package nodejs; scripts/install-deps.sh)"
  exit 1
fi
chromium=${CHROMIUM:-/usr/bin/chromium}
[ -x "$chromium" ] || { echo "FAIL $chromium is not installed (Debian package chromium)"; exit 1; }

study=$work/study
run_compare() {
  "$bin" compare "$src/scenes/simple.json" "$src/scenes/high.json" "$src/scenes/sunset.json" -m point \
    -m "supersample --samples 2x2x1" --frames 0-2 --width 48 --reference 2x2x2 \
    --budgets 1x1x1,2x2x1 -q "$@"
}
if out=$(run_compare --out "$study" 2>&1); then pass; else fail "compare: $out"; fi
for f in index.html results.json results.csv results.md chart.umd.min.js report.js report.css \
  img/simple-grid.png img/high-grid.png img/simple-crops.png img/simple/point-near.png \
  img/high/reference-samples-2x2x2-far.png video/simple.mp4 video/high.mp4 video/sunset.mp4; do
  [ -s "$study/$f" ] && pass || fail "missing $study/$f"
done
grep -q "report: $study/index.html" <<<"$out" && pass || fail "compare does not say where the report is: $out"
# The live page of the study's scenes (sunglint web, docs/web.md), linked from each scene.
[ -s "$study/web/index.html" ] && [ -s "$study/web/data.js" ] && pass || fail "no live page in $study/web"
grep -q 'href="web/index.html?scene=sunset&amp;method=staa&amp;split=point"' "$study/index.html" && pass ||
  fail "the report does not link the live page of sunset"

# The page as a reader opens it.
if shot=$(node "$src/tests/report/check_page.mjs" "$study/index.html" "$work/screenshot.png" \
  --chromium "$chromium" 2>&1); then
  pass
  # 9 pictures (grids, sliders) and 18 crops (3 scenes x 3 columns x near, far); 4 charts of
  # the study, a quality-cost curve and a flicker plot per scene. The colour scene's video
  # (RGB, Rec. 709) decodes like the grey ones.
  grep -q "27 images, 3 videos, 10 charts" <<<"$shot" && pass || fail "unexpected page content: $shot"
  grep -q "18 crops; charts .*chart-flicker-simple.*chart-flicker-high.*chart-flicker-sunset" \
    <<<"$shot" && pass || fail "no crops or flicker charts: $shot"
  # The summary opens the page, one item per scene; the axis labels were measured apart.
  grep -q "summary of 3 scenes; [1-9][0-9]* pairs of axis labels apart" <<<"$shot" && pass ||
    fail "no summary, or no axis labels checked: $shot"
else
  fail "report page: $shot"
fi
# The crops are 2:1 pixels of a 12x6 window of the 48x27 frames (a quarter of each side).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $3 * 256 + $4 "x" $7 * 256 + $8}'; }
[ "$(png_size "$study/img/simple/point-near.png")" = 24x12 ] && pass ||
  fail "crop size $(png_size "$study/img/simple/point-near.png"), wanted 24x12"
# The flicker pixel and its traces are in results.json; the Markdown has the table.
grep -q '"flicker_pixel": {' "$study/results.json" && pass || fail "no flicker pixel in results.json"
grep -q '^Flicker at pixel (' "$study/results.md" && pass || fail "no flicker table in results.md"
# The colour scene: per-channel figures in results.json, .csv and the page.
grep -q '"channels": 3' "$study/results.json" && pass || fail "colour scene not in colour"
grep -q '^sunset,method,point,image,.*,[0-9.e-]*,[0-9.e-]*,[0-9.e-]*$' "$study/results.csv" && pass ||
  fail "no per-channel columns for the colour scene in results.csv"
grep -q 'class="num channels"' "$study/index.html" && pass || fail "no per-channel table in the page"
[ -s "$work/screenshot.png" ] && pass || fail "no screenshot"

# A broken copy must be caught: the check can fail.
broken=$work/broken
cp -r "$study" "$broken"
rm "$broken/img/simple-grid.png" "$broken/video/high.mp4" "$broken/img/high/point-far.png"
sed -i 's|class="crop" src="img/simple/point-near.png" width="24"|class="crop" src="img/simple/point-near.png" width="12"|' \
  "$broken/index.html"
echo 'window.undefinedFunction();' >>"$broken/report.js"
# ... and the summary gone, every method in one colour and dash, the cost chart's time axis
# linear, the log axes' labels packed (1 to 9 in each decade, a label's room taken as
# 1 px), a video of 0.1 s.
sed -i 's|<section id="summary">|<section id="summery">|' "$broken/index.html"
sed -i "s|^  var methods = results.settings.methods;|  palette = palette.map(function () { return '#0072B2'; }); dashes = [[]];\n&|" \
  "$broken/report.js"
sed -i "s|scales: { x: logAxis('ms per frame'), y: logAxis('RMSE') }|scales: { x: { type: 'linear', title: { display: true, text: 'ms per frame' } }, y: logAxis('RMSE') }|" \
  "$broken/report.js"
sed -i 's|var need = horizontal ? 44 : 18;|var need = 1;|; s|var mantissaSets = \[\[1, 2, 5\]|var mantissaSets = [[1, 2, 3, 4, 5, 6, 7, 8, 9]|' \
  "$broken/report.js"
"$bin" render "$src/scenes/sunset.json" -m point --width 48 --frames 0-2 -q --video "$broken/video/sunset.mp4" \
  >/dev/null 2>&1 || fail "render --video for the broken copy"
if bad=$(node "$src/tests/report/check_page.mjs" "$broken/index.html" "$work/broken.png" \
  --chromium "$chromium" 2>&1); then
  fail "a broken report passed the check: $bad"
else
  for want in "image does not load: img/simple-grid.png" "video/high.mp4" "undefinedFunction" \
    "image does not load: img/high/point-far.png" "crop shown shrunk: img/simple/point-near.png" \
    "no summary (section#summary)" "chart chart-rmse: supersample --samples 2x2x1 looks like point" \
    "chart chart-cost-simple: the time axis x is linear, not logarithmic" "labels overlap" \
    "video lasts 0.10 s (under 3 s): video/sunset.mp4"; do
    grep -qF "$want" <<<"$bad" && pass || fail "broken report: '$want' not reported: $bad"
  done
fi
# The videos last at least 3 s: 3 frames of a 30 fps scene play at 1 frame per second.
grep -q '3 frames at 1 frames per second (30 times slower than the scene' "$study/index.html" && pass ||
  fail "the page does not say how the videos play"

# Resume: a second run renders nothing and writes the same results.
cp "$study/results.json" "$work/first.json"
run_compare --out "$study" --no-video >/dev/null 2>&1 && pass || fail "second run"
grep -q '"frames_rendered": 0' "$study/results.json" && pass || fail "second run rendered frames"
if grep -q '"frames_rendered": [1-9]' "$study/results.json"; then fail "second run rendered frames"; else pass; fi

# Bad options name themselves; a missing ffmpeg says what to do.
expect_fail() {
  local name=$1 pattern=$2
  shift 2
  local o
  if o=$("$@" 2>&1); then
    fail "$name: succeeded"
  elif grep -qF -- "$pattern" <<<"$o"; then
    pass
  else
    fail "$name: wanted '$pattern', got: $o"
  fi
}
expect_fail "unknown method" "--method: unknown method 'nope'" \
  "$bin" compare "$src/scenes/simple.json" -m nope --out "$work/x"
expect_fail "bad variant flag" "--method: 'supersample --samples 6x6'" \
  "$bin" compare "$src/scenes/simple.json" -m "supersample --samples 6x6" --out "$work/x"
expect_fail "bad budgets" "--budgets: expected SxSxT" \
  "$bin" compare "$src/scenes/simple.json" -m point --budgets 2x2 --out "$work/x"
expect_fail "bad reference" "--reference: expected SxSxT" \
  "$bin" compare "$src/scenes/simple.json" -m point --reference 8 --out "$work/x"
expect_fail "frames" "--frames: frame 60 is outside" \
  "$bin" compare "$src/scenes/simple.json" -m point --frames 0-60 --out "$work/x"
expect_fail "target" "--equal-cost-target: 'staa' is not one of the methods" \
  "$bin" compare "$src/scenes/simple.json" -m point --equal-cost-target staa --out "$work/x"
expect_fail "no methods" "--method: give at least one" \
  "$bin" compare "$src/scenes/simple.json" --out "$work/x"
expect_fail "paper row" "--paper-row: unknown row 'Nope'" \
  "$bin" compare "$src/scenes/simple.json" -m point --paper-row Nope=point --out "$work/x"
[ -e "$work/x" ] && fail "a failed command left $work/x behind" || pass
expect_fail "no ffmpeg" "ffmpeg: not found; install it" \
  env PATH=/nonexistent "$bin" compare "$src/scenes/simple.json" -m point --frames 0-1 \
  --width 16 --reference 1x1x1 --budgets none -q --out "$work/noff"
if env PATH=/nonexistent "$bin" compare "$src/scenes/simple.json" -m point --frames 0-1 --width 16 \
  --reference 1x1x1 --budgets none -q --no-video --out "$work/noff" >/dev/null 2>&1; then
  pass
else
  fail "--no-video still needs ffmpeg"
fi
"$bin" compare --list-methods | grep -qx point && pass || fail "--list-methods"

# `report` regenerates the Markdown and a README section from results.json.
printf 'top\n<!-- demo:begin -->\nold\n<!-- demo:end -->\nend\n' >"$work/README.md"
if o=$("$bin" report "$study/results.json" --markdown "$work/docs/results.md" \
  --images "$work/docs/img" --readme "$work/README.md" 2>&1); then pass; else fail "report: $o"; fi
grep -q '](img/simple-grid.png)' "$work/docs/results.md" && pass || fail "results.md links"
grep -q '](docs/img/simple-grid.png)' "$work/README.md" && pass || fail "README picture"
grep -q '^| `point` |' "$work/README.md" && pass || fail "README table"
grep -q 'old' "$work/README.md" && fail "README section not replaced" || pass
[ -s "$work/docs/img/high-grid.png" ] && pass || fail "grid not copied"
# Tables only, under a title of one's own.
if o=$("$bin" report "$study/results.json" --markdown "$work/docs/tables.md" --no-images \
  --title "Options study" 2>&1); then pass; else fail "report --no-images: $o"; fi
head -1 "$work/docs/tables.md" | grep -qx '# Options study' && pass || fail "report --title"
grep -q 'grid.png' "$work/docs/tables.md" && fail "report --no-images links a picture" || pass

echo "report_test: $passes passed, $fails failed (screenshot: $work/screenshot.png)"
[ $fails -eq 0 ]
