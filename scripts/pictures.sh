#!/usr/bin/env bash
# The pictures: a `staa` picture and a short video of each of the three picture scenes
# (scenes/sunset.json, scenes/moonlit.json, scenes/midday.json, format sunglint-scene/2)
# and of a generated sea of four FFT cascades (out/scenes/ocean-cascades.json, format /3),
# through the display pipeline (`render --display`: exposure, glare, filmic curve), then
# the README's section between <!-- pictures:begin --> and <!-- pictures:end --> and
# docs/pictures.md rewritten to show them. Nothing in them is edited by hand.
#
#   scripts/pictures.sh [--frames A-B] [--split-only] [path/to/sunglint]      (make pictures)
#
# Writes docs/img/pictures/NAME.png (frame 0, 640x360) and docs/video/NAME.mp4 (frames
# 0-59 by default, 2 s at 30 fps). The four measurement scenes are not drawn here: the
# study (make demo) shows them.
#
# First, the README's opening picture, docs/img/readme-split.webp: the sunset moving, its
# left half rendered by `point` and its right half by `staa`, split at the glitter path
# (frames 0-59 at 480x270 through the display pipeline, the centre 320x180 around the
# path, every second frame at 15 fps: 2 s in real time; an animated WebP of about 300 KiB;
# ffmpeg's libwebp and drawtext with any sans font that fontconfig finds). --split-only
# makes that picture alone (about 3 minutes on 2 cores).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=$root/build/sunglint frames=0-59 split_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift ;;
    --split-only) split_only=1 ;;
    -h | --help) sed -n '2,19p' "$0"; exit 0 ;;
    *) bin=$1 ;;
  esac
  shift
done
[ -x "$bin" ] || { echo "pictures: $bin not found; build first (make build)" >&2; exit 1; }
cd "$root"

# The README's point | staa split.
split_picture() {
  local tmp out=docs/img/readme-split.webp label
  tmp=$(mktemp -d)
  for m in point staa; do
    "$bin" render scenes/sunset.json -m "$m" --width 480 --frames 0-59 --display --exposure 0 -q \
      -o "$tmp/${m}_%04d.png"
  done
  label="fontcolor=white:fontsize=14:font=Sans:box=1:boxcolor=black@0.5:boxborderw=3:y=h-th-8"
  mkdir -p docs/img
  ffmpeg -loglevel error -y -framerate 30 -i "$tmp/point_%04d.png" -framerate 30 -i "$tmp/staa_%04d.png" \
    -filter_complex "[0:v]crop=iw/2:ih:0:0[l];[1:v]crop=iw/2:ih:iw/2:0[r];[l][r]hstack=inputs=2,\
crop=320:180:80:80,drawbox=x=iw/2-1:y=0:w=2:h=ih:color=white@0.8:t=fill,\
drawtext=text=point:x=8:$label,drawtext=text=staa:x=w-tw-8:$label,\
select='not(mod(n\,2))',setpts=N/15/TB" \
    -r 15 -c:v libwebp_anim -lossless 0 -q:v 40 -compression_level 6 -loop 0 "$tmp/split.webp"
  mv "$tmp/split.webp" "$out"
  rm -rf "$tmp"
  echo "pictures: $out ($(($(stat -c %s "$out") / 1024)) KiB)"
}
start=$(date +%s)
split_picture
if [ $split_only -eq 1 ]; then
  echo "pictures: $(($(date +%s) - start)) s"
  exit 0
fi

# name, exposure (stops), caption
scenes=(
  "sunset|0|A sunset glitter path under a visible sun low over the sea (sun 3 degrees up, warm light, zenith-to-horizon sky)"
  "moonlit|3|A moonlit sea: a dim bluish sky and a small bright moon 9 degrees up (3 stops of exposure)"
  "midday|0|Glitter under a high midday sun (65 degrees up, above the frame) on short waves, the water blue with the reflected sky"
  "ocean-cascades|0|A sea as engines make it: four 128 x 128 FFT cascades of a 10 m/s JONSWAP sea (65,536 lattice points; written by \`sunglint ocean --cascades 4 --lattice 128 --wind-speed 10 --seed 1\` into out/scenes/), shaded from the cascades' FFT fields"
)
# The cascaded sea is generated (its sidecars are not kept in the repository).
mkdir -p out/scenes
"$bin" ocean -o out/scenes/ocean-cascades.json --cascades 4 --lattice 128 --wind-speed 10 --seed 1 >/dev/null
scene_file() { [ -f "scenes/$1.json" ] && echo "scenes/$1.json" || echo "out/scenes/$1.json"; }
mkdir -p docs/img/pictures docs/video
section=$(mktemp) page=$(mktemp)
trap 'rm -f "$section" "$page"' EXIT
for entry in "${scenes[@]}"; do
  IFS='|' read -r name exposure caption <<<"$entry"
  file=$(scene_file "$name")
  "$bin" render "$file" -m staa --frame 0 --display --exposure "$exposure" -q \
    -o "docs/img/pictures/$name.png"
  "$bin" render "$file" -m staa --frames "$frames" --exposure "$exposure" -q \
    --video "docs/video/$name.mp4"
  printf '![%s: staa](docs/img/pictures/%s.png)\n\n*%s. `sunglint render %s -m staa --display --exposure %s`; video: [docs/video/%s.mp4](docs/video/%s.mp4) (frames %s).*\n\n' \
    "$name" "$name" "$caption" "$file" "$exposure" "$name" "$name" "$frames" >>"$section"
  printf '## %s\n\n![%s: staa](img/pictures/%s.png)\n\n%s.\n\n    sunglint render %s -m staa --frame 0 --display --exposure %s -o %s.png\n    sunglint render %s -m staa --frames %s --exposure %s --video %s.mp4\n\nVideo: [video/%s.mp4](video/%s.mp4).\n\n' \
    "$name" "$name" "$name" "$caption" "$file" "$exposure" "$name" "$file" "$frames" "$exposure" \
    "$name" "$name" "$name" >>"$page"
done
seconds=$(($(date +%s) - start))
echo "pictures: $seconds s"

# The README's section, between its markers (kept).
awk -v file="$section" '
  /^<!-- pictures:end -->$/ { skip = 0 }
  !skip { print }
  /^<!-- pictures:begin -->$/ { while ((getline line < file) > 0) print line; skip = 1; found = 1 }
  END { if (!found) { print "pictures: README.md has no <!-- pictures:begin --> line" > "/dev/stderr"; exit 1 } }
' README.md >README.md.tmp && mv README.md.tmp README.md
{
  printf '# Pictures\n\n<!-- Generated by scripts/pictures.sh (make pictures): do not edit. -->\n\n'
  printf 'The three picture scenes of `scenes/` (format `sunglint-scene/2`: colour radiances, a\n'
  printf 'zenith-to-horizon sky), rendered with `staa` through the display pipeline of the study\n'
  printf '(`--display`: exposure, glare, the filmic curve; docs/report.md). The images are linear\n'
  printf 'RGB before that pipeline (`.exr`, `.pfm` keep them). The last run took %s s for\n' "$seconds"
  printf 'the README'"'"'s point | staa split and the three pictures and videos (frames %s) on %s\n' \
    "$frames" "$(nproc)"
  printf 'cores, %s.\n\n' "$(date -u +%Y-%m-%d)"
  cat "$page"
} >docs/pictures.md
echo "pictures: docs/img/pictures/, docs/video/, docs/pictures.md, README.md"
