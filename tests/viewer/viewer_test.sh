#!/usr/bin/env bash
# `sunglint view` end to end, under an X server: the scripted run's screenshot equals
# `render --engine gl --display` of the same frame and method (max channel difference at
# most 2/255); a split view's halves equal each method's render; a view saved as a scene
# file renders as the view showed it; without a display, with a display that does not
# open, below OpenGL 4.5 and with a bad scene: a clear error, a non-zero exit, no file; the
# still-frame reference against `render --method reference`; a camera that moves in a scripted
# run (`--orbit-rate`) is seen moving within each shutter, and `--record`'s file renders as
# the view showed it.
# Usage: viewer_test.sh SUNGLINT SOURCE_DIR WORK_DIR
# Runs itself under `xvfb-run -a` (or on $SUNGLINT_TEST_DISPLAY); exits 77 (skipped) when
# there is no Xvfb, unless SUNGLINT_REQUIRE_GL=1.
set -u
bin=$1 src=$2 work=$3
if [ -z "${SG_VIEWER_TEST_INNER:-}" ]; then
  export SG_VIEWER_TEST_INNER=1
  if [ -n "${SUNGLINT_TEST_DISPLAY:-}" ]; then
    DISPLAY=$SUNGLINT_TEST_DISPLAY exec bash "$0" "$@"
  fi
  if ! command -v xvfb-run >/dev/null; then
    echo "xvfb-run is not installed (Debian package xvfb)"
    [ "${SUNGLINT_REQUIRE_GL:-}" = 1 ] && exit 1
    exit 77
  fi
  exec xvfb-run -a -s "-screen 0 1280x1024x24 -nolisten tcp" bash "$0" "$@"
fi
rm -rf "$work" && mkdir -p "$work"
scene=$src/scenes/simple.json
size=(--width 320 --height 180)
fails=0 passes=0
pass() { passes=$((passes + 1)); }
fail() { echo "FAIL $*"; fails=$((fails + 1)); }
run() {  # run NAME CMD...: must succeed
  local name=$1 out
  shift
  if ! out=$("$@" 2>&1); then fail "$name: $out"; return 1; fi
  echo "$out" | tail -1
}
# max_diff A B [X0 X1] <= LIMIT
expect_close() {
  local name=$1 limit=$2 d
  shift 2
  d=$(python3 "$src/tests/viewer/png_diff.py" "$@") || { fail "$name: $d"; return; }
  if [ "$d" -le "$limit" ]; then pass; else fail "$name: max difference $d/255 > $limit/255"; fi
}
expect_apart() {
  local name=$1 d
  shift
  d=$(python3 "$src/tests/viewer/png_diff.py" "$@") || { fail "$name: $d"; return; }
  if [ "$d" -gt 8 ]; then pass; else fail "$name: the pictures do not differ ($d/255)"; fi
}
# expect_refused NAME PATTERN FILE CMD...: non-zero exit, PATTERN in the output, no FILE
expect_refused() {
  local name=$1 pattern=$2 file=$3 out rc
  shift 3
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -eq 0 ]; then fail "$name: exit 0: $out"; return; fi
  if ! grep -qF -- "$pattern" <<<"$out"; then fail "$name: wanted '$pattern', got: $out"; return; fi
  if [ -e "$file" ]; then fail "$name: wrote $file"; return; fi
  pass
}

# 1. The scripted run equals render --engine gl --display of its last frame.
run view-point "$bin" view "$scene" -m point --frames 3 "${size[@]}" --screenshot "$work/view_point.png"
run render-point "$bin" render "$scene" -m point --engine gl --frame 2 "${size[@]}" --display -q \
  -o "$work/render_point.png"
expect_close "view = render (point, frame 2)" 2 "$work/view_point.png" "$work/render_point.png"
run view-colour "$bin" view "$src/scenes/sunset.json" -m staa-temporal --frames 2 "${size[@]}" \
  --screenshot "$work/view_sunset.png"
run render-colour "$bin" render "$src/scenes/sunset.json" -m staa-temporal --engine gl --frame 1 \
  "${size[@]}" --display -q -o "$work/render_sunset.png"
expect_close "view = render (staa-temporal, colour, frame 1)" 2 "$work/view_sunset.png" \
  "$work/render_sunset.png"

# The same with the display pipeline on the GPU (viewer/gpu_display.h; "auto" keeps it on
# the CPU on llvmpipe): glare on the colour scene (it changes the picture), and without.
# taa keeps its history on the GPU from frame to frame: the viewer's frames 0-2 are render's
# frame 2 after the warm-up frames 0 and 1.
run view-taa "$bin" view "$scene" -m taa --frames 3 "${size[@]}" --screenshot "$work/view_taa.png"
run render-taa "$bin" render "$scene" -m taa --taa-warmup 2 --engine gl --frame 2 "${size[@]}" \
  --display -q -o "$work/render_taa.png"
expect_close "view = render (taa, frame 2 after frames 0 and 1)" 2 "$work/view_taa.png" \
  "$work/render_taa.png"
run render-taa-cold "$bin" render "$scene" -m taa --taa-warmup 0 --engine gl --frame 2 \
  "${size[@]}" --display -q -o "$work/render_taa_cold.png"
expect_apart "taa's history changes the picture" "$work/render_taa.png" "$work/render_taa_cold.png"

run view-gpu-point "$bin" view "$scene" -m point --frames 3 "${size[@]}" --display-on gpu \
  --screenshot "$work/view_gpu_point.png"
expect_close "GPU display = render (point, frame 2)" 2 "$work/view_gpu_point.png" \
  "$work/render_point.png"
run view-gpu-colour "$bin" view "$src/scenes/sunset.json" -m staa-temporal --frames 2 "${size[@]}" \
  --display-on gpu --screenshot "$work/view_gpu_sunset.png"
expect_close "GPU display = render (staa-temporal, colour, glare)" 2 "$work/view_gpu_sunset.png" \
  "$work/render_sunset.png"
run view-gpu-noglare "$bin" view "$src/scenes/sunset.json" -m staa-temporal --frames 2 \
  "${size[@]}" --display-on gpu --no-glare --exposure 1.5 --screenshot "$work/view_gpu_ng.png"
run render-noglare "$bin" render "$src/scenes/sunset.json" -m staa-temporal --engine gl --frame 1 \
  "${size[@]}" --display --no-glare --exposure 1.5 -q -o "$work/render_sunset_ng.png"
expect_close "GPU display = render (no glare, exposure 1.5)" 2 "$work/view_gpu_ng.png" \
  "$work/render_sunset_ng.png"
run render-noglare0 "$bin" render "$src/scenes/sunset.json" -m staa-temporal --engine gl --frame 1 \
  "${size[@]}" --display --no-glare -q -o "$work/render_sunset_ng0.png"
expect_apart "the glare changes the picture" "$work/render_sunset.png" "$work/render_sunset_ng0.png"

run view-controls "$bin" view "$scene" -m point --frames 3 "${size[@]}" --show-controls \
  --screenshot "$work/view_controls.png"
expect_apart "--show-controls draws the controls" "$work/view_controls.png" "$work/view_point.png" \
  0 100

# 2. The split view: point on the left, supersample on the right, the divider at the middle.
run view-split "$bin" view "$scene" -m point --split supersample --samples 3x3x1 --frames 3 \
  "${size[@]}" --screenshot "$work/view_split.png"
run render-ss "$bin" render "$scene" -m supersample --samples 3x3x1 --engine gl --frame 2 \
  "${size[@]}" --display -q -o "$work/render_ss.png"
expect_close "split: left half = point" 2 "$work/view_split.png" "$work/render_point.png" 0 160
expect_close "split: right half = supersample" 2 "$work/view_split.png" "$work/render_ss.png" 160 320
expect_apart "split: the methods differ" "$work/render_point.png" "$work/render_ss.png"

# 3. A view with edited light and waves saved as a scene renders as the view showed it.
run view-edited "$bin" view "$scene" -m point --frames 1 "${size[@]}" --sun-elevation 6 \
  --sun-azimuth 4 --sun-radius 0.8 --amplitude-scale 0.7 --screenshot "$work/view_edited.png" \
  --save-scene "$work/edited.json"
run render-edited "$bin" render "$work/edited.json" -m point --engine gl --display -q \
  -o "$work/render_edited.png"
expect_close "saved view = its render" 2 "$work/view_edited.png" "$work/render_edited.png"
run render-unedited "$bin" render "$scene" -m point --engine gl "${size[@]}" --display -q \
  -o "$work/render_point0.png"
expect_apart "the edits change the picture" "$work/view_edited.png" "$work/render_point0.png"

# A camera moved (an orbit, as a left drag does) is the camera of both sides of a split
# and the one the saved scene holds.
run view-orbit "$bin" view "$scene" -m point --split supersample --samples 3x3x1 --frames 1 \
  "${size[@]}" --orbit-yaw -30 --orbit-pitch 5 --screenshot "$work/view_orbit.png" \
  --save-scene "$work/orbit.json"
run render-orbit-point "$bin" render "$work/orbit.json" -m point --engine gl --display -q \
  -o "$work/render_orbit_point.png"
run render-orbit-ss "$bin" render "$work/orbit.json" -m supersample --samples 3x3x1 --engine gl \
  --display -q -o "$work/render_orbit_ss.png"
expect_close "orbited split: left half = the saved scene's point" 2 "$work/view_orbit.png" \
  "$work/render_orbit_point.png" 0 160
expect_close "orbited split: right half = the saved scene's supersample" 2 "$work/view_orbit.png" \
  "$work/render_orbit_ss.png" 160 320
expect_apart "the orbit moves the camera (left half)" "$work/render_orbit_point.png" \
  "$work/render_point0.png" 0 160
expect_apart "the orbit moves the camera (right half)" "$work/render_orbit_point.png" \
  "$work/render_point0.png" 160 320

# 4. The still-frame reference (80x45: llvmpipe's reference is slow): one batch is `render --method reference` of the
# frame; more batches average more seeds (closer to a reference of as many samples); its
# difference to the method is black where the method is that same batch, not otherwise.
tiny=(--width 80 --height 45)
run view-ref1 "$bin" view "$scene" -m point --frames 1 "${tiny[@]}" --reference-batches 1 \
  --screenshot "$work/view_ref1.png"
run render-ref "$bin" render "$scene" -m reference --engine gl --frame 0 "${tiny[@]}" --display -q \
  -o "$work/render_ref.png"
expect_close "reference view, 1 batch = render --method reference" 2 "$work/view_ref1.png" \
  "$work/render_ref.png"
run view-ref4 "$bin" view "$scene" -m point --frames 1 "${tiny[@]}" --reference-batches 4 \
  --screenshot "$work/view_ref4.png"
run render-ref16 "$bin" render "$scene" -m reference --samples 16x16x1 --engine gl --frame 0 \
  "${tiny[@]}" --display -q -o "$work/render_ref16.png"
e1=$(python3 "$src/tests/viewer/png_diff.py" --sum "$work/view_ref1.png" "$work/render_ref16.png")
e4=$(python3 "$src/tests/viewer/png_diff.py" --sum "$work/view_ref4.png" "$work/render_ref16.png")
if [ "$e4" -lt "$e1" ]; then pass; else
  fail "reference view: 4 batches ($e4) not closer than 1 ($e1) to 16x16x1 (sums of |differences|)"
fi
peak() { python3 "$src/tests/viewer/png_diff.py" --peak "$1"; }
run view-refdiff1 "$bin" view "$scene" -m reference --frames 1 "${tiny[@]}" \
  --reference-batches 1 --reference-difference 100 --screenshot "$work/view_refdiff1.png"
p=$(peak "$work/view_refdiff1.png")
[ "$p" -eq 0 ] && pass || fail "reference difference to itself: not black ($p/255)"
run view-refdiff2 "$bin" view "$scene" -m reference --frames 1 "${tiny[@]}" \
  --reference-batches 2 --reference-difference 100 --screenshot "$work/view_refdiff2.png"
p=$(peak "$work/view_refdiff2.png")
[ "$p" -gt 8 ] && pass || fail "reference difference, 2 batches: black ($p/255): one seed only?"
expect_refused "reference batches without frames" "need --frames" "$work/refused.png" \
  "$bin" view "$scene" --reference-batches 2

# 5. A camera in motion: a scripted orbit (30 degrees a second) is keyed over each frame's
# shutter (160x90; supersample with 4 times sees it: motion blur), and the recorded path is a /3
# scene whose render is the view; the last camera held still renders differently. A /3
# scene's own keys are recorded as its path too.
small=(--width 160 --height 90)
blur=(-m supersample --samples 2x2x4)
run view-orbit-rate "$bin" view "$scene" "${blur[@]}" --frames 3 "${small[@]}" --orbit-rate 30 \
  --screenshot "$work/view_flight.png" --record "$work/flight.json" --save-scene "$work/flight_last.json"
run render-flight "$bin" render "$work/flight.json" "${blur[@]}" --engine gl --frame 2 --display -q \
  -o "$work/render_flight.png"
run render-flight-still "$bin" render "$work/flight_last.json" "${blur[@]}" --engine gl --frame 2 \
  --display -q -o "$work/render_flight_still.png"
expect_close "recorded flight = the view (frame 2, in motion)" 2 "$work/view_flight.png" \
  "$work/render_flight.png"
expect_apart "the view's frame is in motion (not the last camera held still)" \
  "$work/view_flight.png" "$work/render_flight_still.png"
grep -q '"sunglint-scene/3"' "$work/flight.json" && pass || fail "--record: not a /3 file"
run view-pan-record "$bin" view "$src/tests/scenes/pan.json" "${blur[@]}" --frames 3 "${small[@]}" \
  --screenshot "$work/view_pan.png" --record "$work/pan_path.json"
run render-pan-record "$bin" render "$work/pan_path.json" "${blur[@]}" --engine gl --frame 2 \
  --display -q -o "$work/render_pan_path.png"
expect_close "a /3 scene's recorded path = the view" 2 "$work/view_pan.png" \
  "$work/render_pan_path.png"
expect_refused "record not json" "--record: must be a .json file" "$work/refused.txt" \
  "$bin" view "$scene" --frames 1 --record "$work/refused.txt"
expect_refused "orbit-rate without frames" "--orbit-rate: need --frames N" "$work/refused.json" \
  "$bin" view "$scene" --orbit-rate 10 --record "$work/refused.json"
expect_refused "orbit of a keyed camera" "the scene's camera is keyed" "$work/refused.json" \
  "$bin" view "$src/tests/scenes/pan.json" --frames 1 --orbit-rate 10 --record "$work/refused.json"

# 6. Refusals: a clear error, a non-zero exit, no file.
shot=$work/refused.png
expect_refused "no display" "no display: DISPLAY is not set" "$shot" \
  env -u DISPLAY -u WAYLAND_DISPLAY "$bin" view "$scene" -m point --frames 1 "${size[@]}" \
  --screenshot "$shot"
expect_refused "display that does not open" "Failed to open display :31999" "$shot" \
  env DISPLAY=:31999 "$bin" view "$scene" -m point --frames 1 "${size[@]}" --screenshot "$shot"
expect_refused "OpenGL below 4.5" "no OpenGL 4.5 core window" "$shot" \
  env MESA_GL_VERSION_OVERRIDE=4.3 "$bin" view "$scene" -m point --frames 1 "${size[@]}" \
  --screenshot "$shot"
expect_refused "bad scene" "amplitude" "$shot" \
  "$bin" view "$src/tests/scenes/bad/amplitude_negative.json" --frames 1 --screenshot "$shot"
expect_refused "screenshot not png" "--screenshot: must be a .png" "$work/refused.exr" \
  "$bin" view "$scene" --frames 1 --screenshot "$work/refused.exr"
expect_refused "edit out of range" "--sun-radius" "$shot" \
  "$bin" view "$scene" --frames 1 --sun-radius 0 --screenshot "$shot"
expect_refused "orbit under the water" "--orbit-yaw, --orbit-pitch: the orbit would take" "$shot" \
  "$bin" view "$scene" --frames 1 --orbit-pitch -60 --screenshot "$shot"
expect_refused "frames past the animation" "--frames" "$shot" \
  "$bin" view "$scene" --frames 61 --screenshot "$shot"

echo "viewer_test: $passes passed, $fails failed"
[ $fails -eq 0 ]
