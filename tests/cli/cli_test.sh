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
expect_fail "no subcommand" "A subcommand is required" "$bin"
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
expect_fail "video folder" "--video: folder '$work/nope' does not exist" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --frames 0-1 --video "$work/nope/x.mp4"
expect_fail "display exr" "--display: applies to .png output" \
  timeout 20 "$bin" render "$colour" "${slow[@]}" --display --out "$work/x.exr"
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

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
