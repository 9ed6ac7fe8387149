#!/usr/bin/env bash
# The README as a new user reads it, checked where a script can check it:
#   - it opens with the moving point | staa split (docs/img/readme-split.webp: an animated
#     WebP of at most 512 KiB), then the two commands, `make demo` and `make test`, as its
#     first lines of commands;
#   - what it says `make demo` runs is what scripts/demo.sh runs (the same scenes), and it
#     never says make demo runs scenes/*.json;
#   - every document of docs/ is listed under "Documentation", and every docs/ path it
#     names exists;
#   - the commands of "Using it" run: each `build/sunglint ...` line, at a tiny size (its
#     --width made 32, bench's --height 18, its --frames 0-1), in a fresh folder with the
#     scenes, the path tables in a temporary cache folder; `view` needs a window and
#     `--slurm` a cluster, so they are only listed; the GL engine's lines run where an
#     OpenGL 4.5 context can be made (required with SUNGLINT_REQUIRE_GL).
# Usage: readme_test.sh SUNGLINT SOURCE_DIR WORK_DIR
set -u
bin=$(realpath "$1") src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
readme=$src/README.md
fails=0 passes=0
pass() { passes=$((passes + 1)); }
fail() {
  echo "FAIL $*"
  fails=$((fails + 1))
}

# 1. The opening: the picture first, then the two commands.
first=$(sed -n '2,$p' "$readme" | grep -v '^[[:space:]]*$' | head -1)
if [[ $first == '!['*'](docs/img/readme-split.webp)' ]]; then pass; else
  fail "the README does not open with docs/img/readme-split.webp (its first line after the title: $first)"
fi
pic=$src/docs/img/readme-split.webp
if [ -f "$pic" ]; then
  size=$(stat -c %s "$pic")
  # RIFF....WEBPVP8X with an ANIM chunk: an animated WebP.
  if [ "$(head -c 4 "$pic")" = RIFF ] && [ "$(head -c 12 "$pic" | tail -c 4)" = WEBP ] &&
    head -c 64 "$pic" | grep -qa ANIM; then pass; else fail "$pic is not an animated WebP"; fi
  [ "$size" -le 524288 ] && pass || fail "$pic is $((size / 1024)) KiB (at most 512 KiB)"
else
  fail "$pic is missing (make pictures)"
fi
commands=$(awk '/^```/ { if (inside) exit; inside = 1; next } inside' "$readme" | sed 's/[[:space:]]*#.*//' |
  grep -v '^[[:space:]]*$' | head -2 | tr '\n' '|')
[ "$commands" = "make demo|make test|" ] && pass ||
  fail "the README's first commands are not 'make demo' and 'make test': $commands"

# 2. What `make demo` runs: the README's list against scripts/demo.sh's.
said=$(grep -o 'make demo .*runs the study of scenes/{[a-z,-]*}\.json' "$readme" | head -1 |
  sed 's/.*{\(.*\)}.*/\1/' | tr ',' '\n' | sort | tr '\n' ' ')
runs=$(sed -n '/compare /,/--out/p' "$src/scripts/demo.sh" | grep -o 'scenes/[a-z-]*\.json' |
  sed 's|scenes/||; s|\.json||' | sort | tr '\n' ' ')
if [ -n "$runs" ] && [ "$said" = "$runs" ]; then pass; else
  fail "the README says make demo runs '$said'; scripts/demo.sh runs '$runs'"
fi
if grep -n 'make demo.*scenes/\*\.json' "$readme"; then fail "the README says make demo runs scenes/*.json (it runs $runs)"; else pass; fi

# 3. Every document listed, every docs/ path there.
docs=$(awk '/^## Documentation/ { on = 1; next } /^## / { on = 0 } on' "$readme")
for d in "$src"/docs/*.md; do
  name=docs/$(basename "$d")
  grep -qF "\`$name\`" <<<"$docs" && pass || fail "$name is not listed under Documentation"
done
for p in $(grep -o 'docs/[A-Za-z0-9_./-]*[A-Za-z0-9_]' "$readme" | sort -u); do
  [ -e "$src/$p" ] && pass || fail "the README names $p, which does not exist"
done

# 4. The commands of "Using it", at a tiny size.
run=$work/run
mkdir -p "$run" "$work/cache"
ln -s "$(realpath "$src/scenes")" "$run/scenes"
export SUNGLINT_CACHE_DIR=$work/cache
gl=0
if "$bin" render "$src/scenes/simple.json" -m point --engine gl --width 8 -q -o "$work/glprobe.pfm" >/dev/null 2>&1; then
  gl=1
elif [ -n "${SUNGLINT_REQUIRE_GL:-}" ]; then
  fail "no OpenGL 4.5 context (SUNGLINT_REQUIRE_GL is set)"
fi
# The block under "## Using it", continuation lines joined.
awk '/^## Using it/ { on = 1; next } on && /^```/ { if (inside) exit; inside = 1; next } on && inside' "$readme" |
  sed -e ':a' -e '/\\$/N; s/\\\n[[:space:]]*/ /; ta' >"$work/commands.txt"
ran=0 skipped=""
while IFS= read -r line; do
  [[ $line == build/sunglint* ]] || continue
  cmd=${line%%  #*}  # the comment after two spaces
  sub=$(awk '{ print $2 }' <<<"$cmd")
  if [ "$sub" = view ]; then
    skipped="$skipped view"
    continue
  fi
  if [[ $cmd == *"--slurm"* ]]; then  # a Slurm cluster and its shared folder
    skipped="$skipped slurm"
    continue
  fi
  if [[ $cmd == *"--engine gl"* ]] && [ $gl -eq 0 ]; then
    skipped="$skipped gl"
    continue
  fi
  cmd=$(sed -E 's/--frames [0-9]+-[0-9]+/--frames 0-1/; s/--width [0-9]+/--width 32/' <<<"$cmd")
  case $sub in
    render | compare) [[ $cmd == *"--width "* ]] || cmd="$cmd --width 32" ;;
    bench) cmd="$cmd --width 32 --height 18" ;;
  esac
  cmd=${cmd/#build\/sunglint/$bin}
  if out=$(cd "$run" && bash -c "$cmd" 2>&1); then
    pass
    ran=$((ran + 1))
  else
    fail "README command: $line
  ran as: $cmd
  $out"
  fi
done <"$work/commands.txt"
[ $ran -ge 12 ] && pass || fail "only $ran of the README's commands ran"
for f in ref.exr point.exr ss.exr seq/point_0001.exr seq/ref_0001.exr diff.png sunset.png sunset.mp4 \
  sea.json out/study/index.html; do
  [ -s "$run/$f" ] && pass || fail "the README's commands did not write $f"
done
echo "readme_test: $ran commands of the README run (not run:${skipped:- none}); $passes passed, $fails failed"
[ $fails -eq 0 ]
