#!/usr/bin/env bash
# End-to-end checks of the `sunglint` command line, as a user meets it: every bad input
# exits non-zero with a message naming its culprit and leaves no output file; the same
# command twice writes the same bytes.
# Usage: cli_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
scene=$src/scenes/simple.json
fails=0 passes=0

# expect_fail NAME PATTERN CMD...: the command must exit non-zero and print PATTERN.
expect_fail() {
  local name=$1 pattern=$2
  shift 2
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -ne 0 ] && grep -qF -- "$pattern" <<<"$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL $name: rc=$rc, wanted '$pattern', got: $out"
    fails=$((fails + 1))
  fi
}
expect_ok() {
  local name=$1
  shift
  local out
  if out=$("$@" 2>&1); then
    passes=$((passes + 1))
  else
    echo "FAIL $name: $out"
    fails=$((fails + 1))
  fi
}
# expect_rc NAME RC PATTERN CMD...: the command must exit with RC and print PATTERN.
expect_rc() {
  local name=$1 want=$2 pattern=$3
  shift 3
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -eq "$want" ] && grep -qF -- "$pattern" <<<"$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL $name: rc=$rc (wanted $want), wanted '$pattern', got: $out"
    fails=$((fails + 1))
  fi
}
# expect_fast NAME SECONDS CMD...: the command must end (any exit code) within SECONDS.
expect_fast() {
  local name=$1 limit=$2
  shift 2
  local t0 t1
  t0=$(date +%s%N)
  timeout "$limit" "$@" >/dev/null 2>&1
  if [ $? -eq 124 ]; then
    echo "FAIL $name: still running after $limit s"
    fails=$((fails + 1))
    return
  fi
  t1=$(date +%s%N)
  passes=$((passes + 1))
  echo "  $name: $(((t1 - t0) / 1000000)) ms"
}
expect_no_file() {
  if [ -e "$2" ] || compgen -G "$2.tmp*" >/dev/null; then
    echo "FAIL $1: $2 (or a temporary) was left behind"
    fails=$((fails + 1))
  else
    passes=$((passes + 1))
  fi
}

expect_fail "unknown method" "--method: unknown method 'nope'" \
  "$bin" render "$scene" --method nope --out "$work/a.exr"
expect_no_file "unknown method" "$work/a.exr"
expect_fail "bad samples" "--samples: expected SxSxT" \
  "$bin" render "$scene" -m reference --samples 8x8 --out "$work/a.exr"
expect_fail "bad extension" "unknown image format '.jpg'" \
  "$bin" render "$scene" -m point --out "$work/a.jpg"
expect_no_file "bad extension" "$work/a.jpg"
expect_fail "missing scene" "missing.json: cannot read" \
  "$bin" render "$work/missing.json" -m point --out "$work/a.exr"
expect_fail "bad scene names key" "surface.waves[3].amplitude: must be >= 0" \
  "$bin" render "$src/tests/scenes/bad/amplitude_negative.json" -m point --out "$work/a.exr"
expect_fail "frame out of range" "--frame: frame 60 is outside the animation [0, 59]" \
  "$bin" render "$scene" -m point --frame 60 --out "$work/a.exr"
expect_fail "unwritable output" "does not exist" \
  "$bin" render "$scene" -m point --width 16 --out "$work/no/such/dir/a.exr"
expect_fail "bad width" "--width" \
  "$bin" render "$scene" -m point --width 0 --out "$work/a.exr"
expect_fail "alias start past the footprint default end" \
  "--alias-start, --alias-end: need 0 <= start < end (got 0.900000, 0.800000)" \
  "$bin" render "$scene" -m staa --alias-start 0.9 --width 16 --out "$work/alias.exr"
expect_no_file "alias start past the default end" "$work/alias.exr"
expect_fail "alias start past the paper's default end" "(got 0.600000, 0.500000)" \
  "$bin" render "$scene" -m staa --footprint none --alias-start 0.6 --width 16 --out "$work/alias.exr"
expect_fail "negative alias start" "--alias-start" \
  "$bin" render "$scene" -m staa --alias-start -1 --width 16 --out "$work/alias.exr"
expect_fail "unknown flag" "--bogus" "$bin" render "$scene" -m point --bogus --out "$work/a.exr"
expect_fail "sequence needs a pattern" "exactly one frame number conversion" \
  "$bin" render "$scene" -m point --frames 0-2 --out "$work/a.exr"
expect_fail "bad frame range" "--frames: expected a frame range A-B" \
  "$bin" render "$scene" -m point --frames 3-1 --out "$work/f_%02d.exr"
expect_fail "no subcommand" "give a subcommand: render, diff, info" "$bin"
expect_fail "lean size" "--lean-size: must be a power of two" \
  "$bin" render "$scene" -m lean --lean-size 1000 --out "$work/a.exr"
expect_no_file "lean size" "$work/a.exr"
expect_fail "lean filter" "--lean-filter" \
  "$bin" render "$scene" -m lean --lean-filter bicubic --out "$work/a.exr"
expect_fail "taa alpha" "--taa-alpha: must be in (0, 1]" \
  "$bin" render "$scene" -m taa --taa-alpha 0 --out "$work/a.exr"
expect_fail "taa clamp" "--taa-clamp" \
  "$bin" render "$scene" -m taa --taa-clamp clip --out "$work/a.exr"
expect_fail "bench taa alpha" "--taa-alpha: must be in (0, 1]" \
  "$bin" bench "$scene" --methods point,taa --taa-alpha 2 --width 16 --height 9
# Method flags: enumerations and numbers, each error naming its flag, no file left.
expect_fail "bad microspec area" "--microspec-area: circle not in {approx,exact}" \
  "$bin" render "$scene" -m microspec --microspec-area circle --out "$work/m.exr"
expect_no_file "bad microspec area" "$work/m.exr"
expect_fail "bad specaa derivatives" "--specaa-derivatives: fd not in {analytic,quad}" \
  "$bin" render "$scene" -m specaa --specaa-derivatives fd --out "$work/m.exr"
expect_fail "bad specaa kernel" "--specaa-kernel: box not in {full,rect}" \
  "$bin" render "$scene" -m specaa --specaa-kernel box --out "$work/m.exr"
expect_fail "bad specaa sigma2" "--specaa-sigma2: must be > 0" \
  "$bin" render "$scene" -m specaa --specaa-sigma2 0 --out "$work/m.exr"
expect_fail "bad specaa kappa" "--specaa-kappa: must be >= 0" \
  "$bin" render "$scene" -m specaa --specaa-kappa -1 --out "$work/m.exr"
expect_fail "bad bruneton nmax" "--bruneton-nmax: must be > --bruneton-nmin" \
  "$bin" render "$scene" -m bruneton --bruneton-nmin 2 --bruneton-nmax 1.5 --out "$work/m.exr"
expect_fail "bad bruneton variance" "--bruneton-min-variance: must be > 0" \
  "$bin" render "$scene" -m bruneton --bruneton-min-variance 0 --out "$work/m.exr"
expect_fail "bad bruneton fresnel" "--bruneton-fresnel: exact not in {fit,integral}" \
  "$bin" render "$scene" -m bruneton --bruneton-fresnel exact --out "$work/m.exr"
expect_no_file "bad method flags" "$work/m.exr"
for m in microspec specaa bruneton; do
  expect_ok "render $m" "$bin" render "$scene" -m "$m" --width 48 -q --out "$work/$m.exr"
done
expect_fail "diff sizes" "image sizes differ" bash -c \
  "'$bin' render '$scene' -m point --width 16 -q --out '$work/s16.exr' && \
   '$bin' render '$scene' -m point --width 32 -q --out '$work/s32.exr' && \
   '$bin' diff '$work/s16.exr' '$work/s32.exr'"
expect_fail "diff missing file" "nothere.exr: cannot read" "$bin" diff "$work/nothere.exr" "$work/s16.exr"
expect_fail "diff png input" "PNG files are pictures" "$bin" diff "$work/x.png" "$work/s16.exr"

# Help exists for every subcommand.
for sub in render diff info bench; do
  expect_ok "help $sub" "$bin" "$sub" --help
done
# The render help lists the baselines and their flags with their defaults.
help=$("$bin" render --help 2>&1)
for want in "microspec:" "specaa:" "bruneton:" "--specaa-sigma2" "0.25" "--bruneton-min-variance" \
  "2e-05" "--microspec-area"; do
  if grep -qF -- "$want" <<<"$help"; then passes=$((passes + 1)); else
    echo "FAIL render help lacks '$want'"
    fails=$((fails + 1))
  fi
done

# Determinism: the same command twice gives the same bytes (two thread counts).
expect_ok "render 1" "$bin" render "$scene" -m reference --samples 2x2x2 --width 96 -j 1 -q --out "$work/r1.exr"
expect_ok "render 2" "$bin" render "$scene" -m reference --samples 2x2x2 --width 96 -j 2 -q --out "$work/r2.exr"
expect_ok "render 3 pfm" "$bin" render "$scene" -m reference --samples 2x2x2 --width 96 -q --out "$work/r3.pfm"
expect_ok "render 4 pfm" "$bin" render "$scene" -m reference --samples 2x2x2 --width 96 -q --out "$work/r4.pfm"
if cmp -s "$work/r1.exr" "$work/r2.exr" && cmp -s "$work/r3.pfm" "$work/r4.pfm"; then
  passes=$((passes + 1))
else
  echo "FAIL determinism: outputs differ"
  fails=$((fails + 1))
fi

# A stateful method (taa) warms up before the first frame: frame 5 alone is the first
# frame of the sequence 5-6, and sequences repeat byte for byte.
expect_ok "taa single" "$bin" render "$scene" -m taa --taa-warmup 3 --frame 5 --width 48 -q --out "$work/t5.pfm"
expect_ok "taa seq" "$bin" render "$scene" -m taa --taa-warmup 3 --frames 5-6 --width 48 -q --out "$work/ts_%02d.pfm"
expect_ok "taa seq again" "$bin" render "$scene" -m taa --taa-warmup 3 --frames 5-6 --width 48 -j 1 -q --out "$work/tt_%02d.pfm"
if cmp -s "$work/t5.pfm" "$work/ts_05.pfm" && cmp -s "$work/ts_06.pfm" "$work/tt_06.pfm"; then
  passes=$((passes + 1))
else
  echo "FAIL taa warm-up: frame 5 alone differs from the sequence's, or sequences differ"
  fails=$((fails + 1))
fi
expect_ok "lean" "$bin" render "$scene" -m lean --lean-size 256 --lean-filter aniso --width 48 -q --out "$work/l.pfm"

# Sequences and their metrics.
expect_ok "sequence" "$bin" render "$scene" -m point --frames 0-2 --width 48 -q --out "$work/p_%02d.pfm"
expect_ok "sequence ref" "$bin" render "$scene" -m supersample --samples 2x2x2 --frames 0-2 --width 48 -q --out "$work/s_%02d.pfm"
out=$("$bin" diff "$work/p_%02d.pfm" "$work/s_%02d.pfm" --frames 0-2 --json 2>&1)
if grep -q '"temporal_error"' <<<"$out" && grep -q '"flicker_b"' <<<"$out"; then
  passes=$((passes + 1))
else
  echo "FAIL sequence diff: $out"
  fails=$((fails + 1))
fi
expect_ok "diff picture" "$bin" diff "$work/r1.exr" "$work/r3.pfm" --out "$work/d.png"
[ -s "$work/d.png" ] && passes=$((passes + 1)) || { echo "FAIL diff picture missing"; fails=$((fails + 1)); }
expect_ok "info" "$bin" info "$scene" --waves
expect_ok "info json" "$bin" info "$scene" --json

# Colour (format /2): RGB files, per-channel metrics; the display pipeline and videos.
colour=$src/scenes/sunset.json
expect_ok "colour exr" "$bin" render "$colour" -m point --width 32 -q --out "$work/c.exr"
expect_ok "colour pfm" "$bin" render "$colour" -m point --width 32 -q --out "$work/c.pfm"
[ "$(head -c 2 "$work/c.pfm")" = PF ] && passes=$((passes + 1)) || { echo "FAIL colour pfm is not PF"; fails=$((fails + 1)); }
[ "$(head -c 2 "$work/r3.pfm")" = Pf ] && passes=$((passes + 1)) || { echo "FAIL grey pfm is not Pf"; fails=$((fails + 1)); }
out=$("$bin" diff "$work/c.exr" "$work/c.pfm" --json 2>&1)
if grep -q '"rmse": 0.0' <<<"$out" && grep -q '"B": {' <<<"$out"; then passes=$((passes + 1)); else
  echo "FAIL colour diff (EXR and PFM of one frame): $out"
  fails=$((fails + 1))
fi
expect_ok "colour frame 1" "$bin" render "$colour" -m point --width 32 -q --out "$work/c2.exr" --frame 1
out=$("$bin" diff "$work/c2.exr" "$work/c.exr" 2>&1)
grep -q '^rmse .*(R .*, G .*, B .*)' <<<"$out" && passes=$((passes + 1)) || { echo "FAIL per-channel diff: $out"; fails=$((fails + 1)); }
# PNG colour type (IHDR byte 25): 2 = RGB for colour, 0 = grey.
png_type() { od -An -tu1 -j25 -N1 "$1" | tr -d ' '; }
expect_ok "colour png" "$bin" render "$colour" -m point --width 32 -q --out "$work/c.png"
expect_ok "colour png display" "$bin" render "$colour" -m point --width 32 -q --display --out "$work/cd.png"
expect_ok "grey png display" "$bin" render "$scene" -m point --width 32 -q --display --out "$work/gd.png"
if [ "$(png_type "$work/c.png")" = 2 ] && [ "$(png_type "$work/gd.png")" = 0 ] && ! cmp -s "$work/c.png" "$work/cd.png"; then
  passes=$((passes + 1))
else
  echo "FAIL png colour types or --display has no effect"
  fails=$((fails + 1))
fi
# --video: the range in one command, no --out needed, same bytes twice.
expect_ok "video" "$bin" render "$colour" -m point --width 32 --frames 0-3 -q --video "$work/v.mp4"
expect_ok "video again" "$bin" render "$colour" -m point --width 32 --frames 0-3 -q --video "$work/v2.mp4"
if [ "$(od -An -c -j4 -N4 "$work/v.mp4" | tr -d ' ')" = ftyp ] && cmp -s "$work/v.mp4" "$work/v2.mp4"; then
  passes=$((passes + 1))
else
  echo "FAIL --video: no MP4, or two runs differ"
  fails=$((fails + 1))
fi
expect_ok "video and frames" "$bin" render "$scene" -m point --width 32 --frames 0-1 -q \
  --video "$work/g.mp4" --display --out "$work/vf_%d.png"
[ -s "$work/g.mp4" ] && [ -s "$work/vf_1.png" ] && passes=$((passes + 1)) || { echo "FAIL --video with --out"; fails=$((fails + 1)); }
# Bad combinations name the flag and fail before rendering: the reference at 64x64x64
# samples per pixel would take minutes.
slow=(-m reference --samples 64x64x64)
expect_fail "video without frames" "--video: needs --frames A-B" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --video "$work/x.mp4"
expect_fail "video not mp4" "--video: must be an .mp4 file (got '$work/x.avi')" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --frames 0-1 --video "$work/x.avi"
expect_fail "video folder" "--video: $work/nope/x.mp4: cannot write: folder '$work/nope' does not exist" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --frames 0-1 --video "$work/nope/x.mp4"
expect_fail "display exr" "--display: applies to .png output" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --display --out "$work/x.exr"
expect_rc "variance not png" 2 "--variance-out: must be .exr or .pfm" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --variance-out "$work/v.png" --out "$work/x.exr"
expect_rc "variance of a method without noise" 2 "--variance-out: method point" \
  timeout 20 "$bin" render "$scene" -m point --variance-out "$work/v.pfm" --out "$work/x.exr"
# The reference measures its noise: printed, and each pixel's variance written.
expect_rc "reference standard error" 0 "reference: standard error" \
  "$bin" render "$colour" -m reference --samples 2x2x1 --width 48 -q --variance-out \
  "$work/var.pfm" --out "$work/rv.pfm"
[ -s "$work/var.pfm" ] && passes=$((passes + 1)) || { echo "FAIL --variance-out wrote nothing"; fails=$((fails + 1)); }
expect_fail "no glare alone" "--no-glare: needs --display or --video" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --no-glare --out "$work/x.png"
expect_fail "no output" "--out: required (or --video FILE.mp4 with --frames A-B)" \
  timeout 20 "$bin" render "$colour" "${slow[@]}"
expect_fail "video and frame" "--frame" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --frame 2 --video "$work/x.mp4"
expect_fail "video without ffmpeg" "--video: ffmpeg: not found" \
  env PATH=/nonexistent "$bin" render "$colour" "${slow[@]}" --frames 0-1 --video "$work/x.mp4"
for f in x.mp4 x.avi x.exr x.png; do expect_no_file "bad video/display flags" "$work/$f"; done
expect_fail "format /1 with colour" "light.radiance: an [r, g, b] radiance needs" \
  "$bin" render "$src/tests/scenes/bad/v1_rgb_light.json" -m point --out "$work/x.exr"
expect_ok "info colour" "$bin" info "$colour"
# A moving camera (format /3): info reports each segment's speed and turn rate, in words
# and in JSON; the pan renders.
pan=$src/tests/scenes/pan.json
out=$("$bin" info "$pan" 2>&1)
if grep -q "^camera       0 to 2 s: speed 1.5 m/s, turn rate 23.15 deg/s" <<<"$out"; then
  passes=$((passes + 1))
else
  echo "FAIL info of a moving camera: $out"
  fails=$((fails + 1))
fi
out=$("$bin" info "$pan" --json 2>&1)
if grep -q '"speed_m_per_s": 1.5' <<<"$out" && grep -q '"turn_rate_deg_per_s": 23.15' <<<"$out"; then
  passes=$((passes + 1))
else
  echo "FAIL info json of a moving camera: $out"
  fails=$((fails + 1))
fi
expect_ok "render a moving camera" "$bin" render "$pan" -m supersample --samples 2x2x2 --width 32 -q \
  --out "$work/pan.exr"

# The engines: --engine on render, bench and compare (per variant or for the whole study).
expect_rc "engine unknown" 2 "--engine: unknown engine 'vulkan' (choose cpu or gl)" \
  "$bin" render "$scene" -m point --engine vulkan -o "$work/x.exr"
expect_rc "engine gl lacks footprint exact" 2 "--footprint exact: not on the GL engine" \
  "$bin" render "$scene" -m staa --footprint exact --engine gl -o "$work/x.exr"
expect_rc "bench variant on gl lacks footprint exact" 2 "--footprint exact: not on the GL engine" \
  "$bin" bench "$scene" --methods "point,staa --footprint exact --engine gl" --width 16 --height 9
expect_rc "compare engine gl lacks footprint exact" 2 "--method: 'staa --footprint exact --engine gl': --footprint exact: not on the GL engine" \
  "$bin" compare "$scene" -m "staa --footprint exact" --engine gl --frames 0-0 --no-video -q --out "$work/gls"
expect_no_file "engine usage errors" "$work/x.exr"
if "$bin" render "$scene" -m point --engine gl --width 8 -q -o "$work/glprobe.pfm" >/dev/null 2>&1; then
  # staa-temporal on the sunset: the path and the visible sun over the pixel, on both engines.
  expect_ok "render gl" "$bin" render "$colour" -m staa-temporal --engine gl --width 48 -q -o "$work/gl.pfm"
  expect_ok "render cpu float" "$bin" render "$colour" -m staa-temporal --precision float --width 48 -q -o "$work/cf.pfm"
  out=$("$bin" diff "$work/gl.pfm" "$work/cf.pfm" --json 2>&1)
  if python3 -c 'import json,sys; sys.exit(0 if json.loads(sys.argv[1])["rmse"] < 1e-4 else 1)' "$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL gl vs cpu float: $out"
    fails=$((fails + 1))
  fi
  # bench on the GL engine: each frame's GPU time within its wall time (the medians of the
  # same frames), and the sampling methods' samples per second.
  out=$("$bin" bench "$scene" --methods "point,staa-temporal,supersample --samples 2x2x1" --engine gl \
    --width 32 --height 18 2>&1)
  if [ "$(grep -c '| gl (GPU timer; frame' <<<"$out")" = 3 ] &&
    grep -q '^| simple | staa-temporal | gl (GPU timer; frame [0-9.]* ms) | [0-9.]* | [0-9.]* | - | - |$' <<<"$out" &&
    grep -q '^| simple | point | gl (GPU timer; frame [0-9.]* ms) | [0-9.]* | 1.00 | [0-9.e+]* | - |$' <<<"$out" &&
    grep -q '^| simple | supersample --samples 2x2x1 | gl .* | [0-9.]* | [0-9.]* | [0-9.e+]* | [0-9.e+]* |$' <<<"$out" &&
    awk -F'|' '/GPU timer/ { split($4, a, "frame "); if ($5 + 0 > a[2] + 0) bad = 1 } END { exit bad }' <<<"$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL bench --engine gl (a GPU time past its frame's, or an empty column): $out"
    fails=$((fails + 1))
  fi
  # The GL program's preparation is announced with its time (SUNGLINT_GL_NOTICE_AFTER=0: every
  # one; by default those past a second), and the driver's shader cache (Mesa's, in a fresh
  # folder here) makes a second process's short.
  gl_prep() {
    SUNGLINT_GL_NOTICE_AFTER=${notice:-} MESA_SHADER_CACHE_DIR=$work/mesa_cache "$bin" render "$scene" \
      -m point --engine gl --width 16 -q -o "$work/glprep.pfm" 2>&1
  }
  took() { sed -n 's/^sunglint: the GL program of point took \([0-9.]*\) s to prepare$/\1/p' <<<"$1"; }
  first=$(notice=0 gl_prep) second=$(notice=0 gl_prep) third=$(gl_prep)
  t1=$(took "$first") t2=$(took "$second")
  if grep -q "^sunglint: preparing the GL program of point (" <<<"$first" && [ -n "$t1" ] && [ -n "$t2" ] &&
    ! grep -q "preparing" <<<"$third"; then
    passes=$((passes + 1))
  else
    echo "FAIL GL program preparation not announced, or announced by default when quick: $first / $second / $third"
    fails=$((fails + 1))
  fi
  # Where the first run compiled (0.3 s or more: the driver honours MESA_SHADER_CACHE_DIR),
  # the second takes it from the cache: at most a third of the time.
  if [ -n "$t1" ] && [ -n "$t2" ] && awk -v a="$t1" -v b="$t2" 'BEGIN { exit !(a >= 0.3 && b > a / 3) }'; then
    echo "FAIL the second process prepared the GL program in $t2 s, the first in $t1 s: no cache"
    fails=$((fails + 1))
  else
    passes=$((passes + 1))
    echo "  GL program preparation: $t1 s, then $t2 s"
  fi
  expect_rc "compare cpu and gl" 0 "point --engine gl" \
    "$bin" compare "$scene" -m point -m "point --engine gl" --frames 0-1 --width 16 --reference 1x1x1 \
    --budgets none --no-video -q --out "$work/glstudy"
  grep -q '"point --engine gl"' "$work/glstudy/results.json" && passes=$((passes + 1)) ||
    { echo "FAIL compare: no 'point --engine gl' in results.json"; fails=$((fails + 1)); }
elif [ -n "${SUNGLINT_REQUIRE_GL:-}" ]; then
  echo "FAIL no OpenGL 4.5 context (SUNGLINT_REQUIRE_GL is set): $("$bin" render "$scene" -m point --engine gl --width 8 -q -o "$work/glprobe.pfm" 2>&1)"
  fails=$((fails + 1))
else
  echo "skipped the GL engine's CLI checks: no OpenGL 4.5 context"
fi

# ---------------------------------------------------------------------------------------
# Bad and extreme input (docs/scene-format-notes.md; README "Exit codes").
edge=$src/tests/scenes/edge bad=$src/tests/scenes/bad

# Outputs are checked before the first pixel: a missing or unwritable folder fails at
# once (the full-size reference takes seconds), with exit code 1 and no file.
expect_rc "missing folder" 1 "folder '$work/nodir' does not exist (--mkdir creates it)" \
  "$bin" render "$scene" -m reference -o "$work/nodir/r.exr"
expect_fast "missing folder fails before rendering" 3 \
  "$bin" render "$scene" -m reference -o "$work/nodir/r.exr"
expect_no_file "missing folder" "$work/nodir"
if [ "$(id -u)" = 0 ]; then ro=/sys; else ro=$work/readonly && mkdir -p "$ro" && chmod 555 "$ro"; fi
expect_rc "unwritable folder" 1 "cannot write in folder '$ro'" \
  "$bin" render "$scene" -m reference -o "$ro/r.exr"
expect_fast "unwritable folder fails before rendering" 3 \
  "$bin" render "$scene" -m reference -o "$ro/r.exr"
expect_rc "output is a folder" 1 "cannot write: it is a folder" \
  bash -c "mkdir -p '$work/isdir.exr' && '$bin' render '$scene' -m point -o '$work/isdir.exr'"
# The README's sequence example, in a fresh folder, with --mkdir (it says so first).
mkdir -p "$work/fresh"
expect_rc "readme sequence without --mkdir" 1 "folder 'seq' does not exist" \
  bash -c "cd '$work/fresh' && '$bin' render '$scene' -m point --frames 0-2 --width 16 -o seq/point_%04d.exr"
expect_rc "readme sequence with --mkdir" 0 "created folder 'seq' (--mkdir)" \
  bash -c "cd '$work/fresh' && '$bin' render '$scene' -m point --frames 0-2 --width 16 -o seq/point_%04d.exr --mkdir"
for f in 0 1 2; do
  [ -s "$work/fresh/seq/point_000$f.exr" ] && passes=$((passes + 1)) || {
    echo "FAIL readme sequence: seq/point_000$f.exr missing"
    fails=$((fails + 1))
  }
done
expect_rc "diff --out into a missing folder" 1 "does not exist (--mkdir creates it)" \
  "$bin" diff "$work/r1.exr" "$work/r3.pfm" --out "$work/nodir2/d.png"
expect_rc "diff --out --mkdir" 0 "created folder" \
  "$bin" diff "$work/r1.exr" "$work/r3.pfm" --out "$work/newdir/d.png" --mkdir
expect_rc "compare into a file" 1 "--out: '$work/r1.exr' is not a folder" \
  "$bin" compare "$scene" -m point --frames 0-0 --width 16 --no-video -q --out "$work/r1.exr"
expect_rc "compare into an unwritable folder" 1 "--out: cannot write in folder '$ro'" \
  "$bin" compare "$scene" -m point --frames 0-0 --no-video -q --out "$ro/study"
expect_fast "compare into an unwritable folder fails before rendering" 3 \
  "$bin" compare "$scene" -m point --frames 0-0 --no-video -q --out "$ro/study"
expect_rc "report into a missing folder" 1 "does not exist" \
  "$bin" report "$work/no_results.json" --markdown "$work/nodir3/r.md"

# Displaced water with the camera under a crest: every method renders (the writers refuse
# a non-finite pixel, so exit code 0 means every pixel is finite).
for m in point reference supersample staa lean taa microspec specaa bruneton; do
  case $m in
    reference | supersample) flags=(--samples 2x2x2) ;;
    lean) flags=(--lean-size 256) ;;
    taa) flags=(--taa-warmup 2) ;;
    *) flags=() ;;
  esac
  expect_rc "under the crests: $m" 0 "-> $work/below_$m.pfm" \
    "$bin" render "$edge/camera_below_crests.json" -m "$m" --width 48 "${flags[@]}" -q \
    -o "$work/below_$m.pfm"
done
expect_rc "under the crests: finite" 0 "rmse     0" \
  "$bin" diff "$work/below_staa.pfm" "$work/below_staa.pfm"
# The baselines count the pixels where their model fails (here: all of frame 0).
expect_rc "fallback pixels counted" 0 ", 1296 fallback pixels" \
  "$bin" render "$edge/camera_below_crests.json" -m lean --lean-size 256 --width 48 -q \
  -o "$work/below_lean.pfm"
# The shortest and longest waves at the breaking steepness on displaced water: bounded
# work (every method on every edge scene: EdgeScenes.EveryMethodIsFinite).
for m in point staa; do
  expect_rc "extreme waves: $m" 0 "-> $work/extreme.pfm" \
    timeout 60 "$bin" render "$edge/extreme_waves.json" -m "$m" --width 64 -q -o "$work/extreme.pfm"
done

# diff refuses non-finite input, naming the file and the pixel count.
python3 - "$work" <<'PY'
import struct, sys
w, h = 4, 3
vals = [0.5] * (w * h)
vals[5] = float("nan")
vals[7] = float("inf")
with open(sys.argv[1] + "/nan.pfm", "wb") as f:
    f.write(b"Pf\n%d %d\n-1.0\n" % (w, h) + struct.pack("<%df" % (w * h), *vals))
    vals[5] = vals[7] = 0.5
with open(sys.argv[1] + "/fine.pfm", "wb") as f:
    f.write(b"Pf\n%d %d\n-1.0\n" % (w, h) + struct.pack("<%df" % (w * h), *vals))
PY
expect_rc "diff of NaN" 1 "$work/nan.pfm: 2 of 12 pixels are not finite (NaN or infinite)" \
  "$bin" diff "$work/nan.pfm" "$work/fine.pfm"
expect_rc "diff of NaN as the reference" 1 "$work/nan.pfm: 2 of 12 pixels are not finite" \
  "$bin" diff "$work/fine.pfm" "$work/nan.pfm"

# Extreme values are rejected by the scene loader with the key (exit code 1).
expect_rc "wave vector 1e8" 1 "surface.waves[0].wave_vector: the wavelength 2 pi / |k| must be in" \
  "$bin" render "$bad/wave_vector_huge.json" -m point -o "$work/x.exr"
expect_rc "amplitude 1e15" 1 "surface.waves[0].amplitude: the steepness amplitude * |wave_vector|" \
  "$bin" render "$bad/amplitude_steep.json" -m reference -o "$work/x.exr"
expect_rc "light radiance 1e308" 1 "light.radiance: must be at most 1e+10" \
  "$bin" render "$bad/light_radiance_huge.json" -m staa -o "$work/x.exr"
expect_rc "camera y 1e308" 1 "camera.position: must be within 100000 m of the origin" \
  "$bin" info "$bad/camera_high.json"
expect_rc "t0 1e308" 1 "animation.t0: must be in [-1e+07, 1e+07] s, got 1e+308" \
  "$bin" render "$bad/t0_huge.json" -m point -o "$work/x.exr"
expect_rc "duplicate key" 1 "surface.waves[2].amplitude: duplicate key" \
  "$bin" info "$bad/duplicate_key.json"
expect_no_file "rejected scenes" "$work/x.exr"
# Files that are not regular files fail at once.
expect_rc "info /dev/zero" 1 "/dev/zero: cannot read: not a regular file" "$bin" info /dev/zero
expect_fast "info /dev/zero is immediate" 5 "$bin" info /dev/zero
expect_rc "render a folder" 1 "$work: cannot read: a folder" "$bin" render "$work" -m point -o "$work/x.exr"
mkfifo "$work/fifo.json"
expect_rc "info a fifo" 1 "fifo.json: cannot read: not a regular file" "$bin" info "$work/fifo.json"
expect_fast "info a fifo is immediate" 5 "$bin" info "$work/fifo.json"

# Usage errors exit with 2, naming the flag; failed work with 1; help with 0.
expect_rc "exposure nan" 2 "--exposure: must be a number in [-64, 64] (got 'nan')" \
  "$bin" render "$scene" -m point --exposure nan -o "$work/x.png"
expect_no_file "exposure nan" "$work/x.png"
expect_rc "width abc" 2 "--width: must be an integer in [1, 16384] (got 'abc')" \
  "$bin" render "$scene" -m point --width abc -o "$work/x.exr"
expect_rc "threads x" 2 "--threads: must be an integer in [0, 1024] (got 'x')" \
  "$bin" render "$scene" -m point -j x -o "$work/x.exr"
expect_rc "unknown flag" 2 "--bogus" "$bin" render "$scene" -m point --bogus -o "$work/x.exr"
expect_rc "missing flag" 2 "--out: required" "$bin" render "$scene" -m point
expect_rc "no subcommand" 2 "sunglint: give a subcommand: render, diff, info, bench, compare, report, ocean, view" "$bin"
expect_rc "unknown method" 2 "--method: unknown method 'nope'" \
  "$bin" render "$scene" -m nope -o "$work/x.exr"
expect_rc "frame past the animation" 2 "--frame: frame 60 is outside the animation" \
  "$bin" render "$scene" -m point --frame 60 -o "$work/x.exr"
expect_rc "taa alpha nan" 2 "--taa-alpha: must be a finite number (got 'nan')" \
  "$bin" render "$scene" -m taa --taa-alpha nan -o "$work/x.exr"
expect_rc "alias start nan" 2 "--alias-start: must be a number in [0, 100] (got 'nan')" \
  "$bin" render "$scene" -m staa --alias-start nan -o "$work/x.exr"
expect_rc "diff peak nan" 2 "--peak: must be a finite number (got 'nan')" \
  "$bin" diff "$work/r1.exr" "$work/r3.pfm" --peak nan
expect_rc "bench frame" 2 "--frame: frame 99 is outside the animation" \
  "$bin" bench "$scene" --methods point --frame 99 --width 16 --height 9
expect_rc "compare variant flag" 2 "--method: 'point --bogus'" \
  "$bin" compare "$scene" -m "point --bogus" --out "$work/study"
expect_rc "bad scene is failed work" 1 "surface.waves[3].amplitude: must be >= 0" \
  "$bin" render "$bad/amplitude_negative.json" -m point -o "$work/x.exr"
expect_rc "help" 0 "Exit codes" "$bin" --help
expect_rc "render help" 0 "--mkdir" "$bin" render --help

# The messages a new user meets, each with its text and exit code: "sunglint: " first, the
# culprit named and the way out said.
# expect_rc_without NAME RC PATTERN ABSENT CMD...: as expect_rc, and ABSENT not printed.
expect_rc_without() {
  local name=$1 want=$2 pattern=$3 absent=$4
  shift 4
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ $rc -eq "$want" ] && grep -qF -- "$pattern" <<<"$out" && ! grep -qF -- "$absent" <<<"$out"; then
    passes=$((passes + 1))
  else
    echo "FAIL $name: rc=$rc (wanted $want), wanted '$pattern' without '$absent', got: $out"
    fails=$((fails + 1))
  fi
}
subs="render, diff, info, bench, compare, report, ocean, view"
expect_rc "unknown subcommand" 2 "sunglint: unknown subcommand 'frobnicate'; the subcommands are $subs" \
  "$bin" frobnicate
expect_rc "misspelt subcommand" 2 "sunglint: unknown subcommand 'rendr' (did you mean render?)" \
  "$bin" rendr "$scene"
expect_rc "unknown flag before the subcommand" 2 "sunglint: unknown flag '--frob'; give a subcommand: $subs" \
  "$bin" --frob
expect_rc_without "misspelt flag" 2 "sunglint: render: unknown flag '--widht' (did you mean --width?)" \
  "not expected" "$bin" render "$scene" -m point --widht 100 -o "$work/x.exr"
expect_rc "misspelt flag of bench" 2 "sunglint: bench: unknown flag '--metods' (did you mean --methods?)" \
  "$bin" bench "$scene" --metods point
expect_rc "misspelt flag of a method variant" 2 \
  "sunglint: --method: 'staa --ndff uniform': unknown flag '--ndff' (did you mean --ndf?)" \
  "$bin" compare "$scene" -m "staa --ndff uniform" --out "$work/study"
expect_rc "misspelt global flag" 2 "unknown flag '--cach-dir' (did you mean --cache-dir?)" \
  "$bin" render "$scene" -m point --cach-dir "$work" -o "$work/x.exr"
expect_rc "unexpected argument" 2 "sunglint: render: unexpected argument '$scene'" \
  "$bin" render "$scene" "$scene" -m point -o "$work/x.exr"
expect_rc "CLI11's error, prefixed" 2 "sunglint: scene is required" "$bin" render -m point -o "$work/x.exr"
expect_rc "the help of the subcommand" 2 "Run 'sunglint render --help' for more information." \
  "$bin" render -m point -o "$work/x.exr"
# Every line of a command-line error is sunglint's (no bare CLI11 line).
for args in "frobnicate" "render $scene -m point --widht 100" "render -m point" "render $scene -m point --width"; do
  # shellcheck disable=SC2086
  lines=$("$bin" $args 2>&1 | grep -cvE "^(sunglint: |Run 'sunglint)")
  [ "$lines" = 0 ] && passes=$((passes + 1)) || { echo "FAIL '$args': a line without 'sunglint: '"; fails=$((fails + 1)); }
done
# The real cause of an unwritable folder: /proc exists, but no file can be made there.
expect_rc_without "folder on a virtual file system" 1 \
  "--out: /proc/x.png: cannot write in folder '/proc': it is on the kernel's virtual proc file system" \
  "'/proc': No such file" "$bin" render "$scene" -m point -o /proc/x.png
# A JSON syntax error: the file, the line and the column, and no key blamed.
printf '{\n  "format": "sunglint-scene/1",\n  "image": {\n    "width": 16,\n' >"$work/truncated.json"
expect_rc_without "truncated scene" 1 \
  "sunglint: $work/truncated.json: line 5, column 1: invalid JSON (unexpected end of input; expected string literal)" \
  "image:" "$bin" info "$work/truncated.json"
printf '{"format": "sunglint-scene/1", "image": {"width": 16 "height": 9}}' >"$work/comma.json"
expect_rc_without "missing comma" 1 "$work/comma.json: line 1, column 61: invalid JSON (unexpected string literal; expected '}')" \
  "image.width" "$bin" render "$work/comma.json" -m point -o "$work/x.exr"
# A flag the method does not take is refused, naming the method (it was ignored).
expect_rc "flag of another method" 2 \
  "sunglint: --samples: not a flag of method point (it configures supersample, reference)" \
  "$bin" render "$scene" -m point --samples 4x4x1 -o "$work/x.exr"
expect_rc "flag of another method, staa" 2 "--lean-size: not a flag of method staa (it configures lean)" \
  "$bin" render "$scene" -m staa --lean-size 256 -o "$work/x.exr"
expect_rc "bench flag of none of its methods" 2 \
  "--taa-alpha: not a flag of any of the methods point, staa (it configures taa)" \
  "$bin" bench "$scene" --methods point,staa --taa-alpha 0.5 --width 16 --height 9
expect_rc "bench flag of one of its methods" 0 "| taa | cpu |" \
  "$bin" bench "$scene" --methods point,taa --taa-alpha 0.5 --width 16 --height 9
# bench --counters: the kernel's work per pixel, the counting methods only.
expect_rc "bench counters" 0 "| point | 2.8 / 5 | 5.6 / 10 |" \
  "$bin" bench "$scene" --methods point,staa --counters
expect_rc "bench counters of a method without a counting render" 2 \
  "--counters: no counting render for 'reference'" \
  "$bin" bench "$scene" --methods point,reference --counters --width 16 --height 9
expect_rc "compare variant with another method's flag" 2 \
  "--method: 'staa --seed 2': --seed: not a flag of method staa (it configures supersample, reference)" \
  "$bin" compare "$scene" -m "staa --seed 2" --out "$work/study"
expect_rc "view with another method's flag" 2 "--samples: not a flag of any of the methods point, staa" \
  "$bin" view "$scene" -m point --split staa --samples 4x4x1
expect_no_file "flags of other methods" "$work/x.exr"
# The viewer has no CPU engine: its message does not send the user to one.
expect_rc_without "view --split of an option the GL engine lacks" 2 "--footprint exact: not in the viewer" \
  "--engine cpu" "$bin" view "$scene" -m point --split staa --footprint exact
expect_rc_without "view --footprint exact" 2 "--footprint exact: not in the viewer" "--engine cpu" \
  "$bin" view "$scene" -m staa --footprint exact

# Progress: on a terminal a bar; in a log one line per frame; none with -q.
log=$("$bin" render "$scene" -m point --frames 0-2 --width 16 -o "$work/pl_%02d.pfm" 2>&1 >/dev/null)
if [ "$(grep -c '^point frame [0-2] ' <<<"$log")" = 3 ] && [ "$(wc -l <<<"$log")" = 3 ]; then
  passes=$((passes + 1))
else
  echo "FAIL progress in a log: wanted 3 lines, one per frame, got: $log"
  fails=$((fails + 1))
fi
quiet=$("$bin" render "$scene" -m point --frames 0-2 --width 16 -q -o "$work/pl_%02d.pfm" 2>&1 >/dev/null)
[ -z "$quiet" ] && passes=$((passes + 1)) || { echo "FAIL -q printed: $quiet"; fails=$((fails + 1)); }
tty=$(script -qec "'$bin' render '$scene' -m point --frames 0-2 --width 16 -o '$work/pt_%02d.pfm'" /dev/null 2>&1)
if grep -qF "[##############################] 100.0%" <<<"$tty" && ! grep -q "point frame" <<<"$tty"; then
  passes=$((passes + 1))
else
  echo "FAIL progress on a terminal: wanted a bar, got: $tty"
  fails=$((fails + 1))
fi

# The path-table cache is announced once, where it is written, and its folder can be chosen.
out=$(SUNGLINT_CACHE_DIR="$work/cache_env" "$bin" render "$scene" -m staa --width 16 -q -o "$work/c.pfm" 2>&1)
if grep -qF "cached them in $work/cache_env/path_tables.bin" <<<"$out" && [ -s "$work/cache_env/path_tables.bin" ]; then
  passes=$((passes + 1))
else
  echo "FAIL cache announcement: $out"
  fails=$((fails + 1))
fi
out=$(SUNGLINT_CACHE_DIR="$work/cache_env" "$bin" render "$scene" -m staa --width 16 -q -o "$work/c.pfm" 2>&1)
if grep -q "path-integral" <<<"$out"; then
  echo "FAIL cache announced again when it was read: $out"
  fails=$((fails + 1))
else
  passes=$((passes + 1))
fi
# --cache-dir wins over the environment: with the environment pointing at a folder that
# cannot exist, the tables are read from --cache-dir's folder, silently (no generation:
# generating them takes a minute in the sanitizer build).
out=$(SUNGLINT_CACHE_DIR=/proc/none "$bin" render "$scene" -m staa --width 16 -q -o "$work/c.pfm" \
  --cache-dir "$work/cache_env" 2>&1)
if [ $? -eq 0 ] && ! grep -q "path-integral" <<<"$out"; then
  passes=$((passes + 1))
else
  echo "FAIL --cache-dir not used: $out"
  fails=$((fails + 1))
fi

# A clone stands alone: no paths into ../shared and no internal issue numbers in the docs,
# the README or the code's comments.
hits=$(cd "$src" && grep -rnE '\.\./shared|shared/(papers|spec|scenes)|[Ii]ssues? #?[0-9]' README.md docs src tests scripts \
  --include='*.md' --include='*.h' --include='*.cpp' --include='*.sh' --include='*.py' --include='*.glsl' 2>/dev/null |
  grep -v "^tests/cli/cli_test.sh:")
[ -z "$hits" ] && passes=$((passes + 1)) || { echo "FAIL references a clone lacks: $hits"; fails=$((fails + 1)); }

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
