#!/usr/bin/env bash
# The spectrum-generated scenes of scenes/, written by `sunglint ocean` (docs/ocean.md):
#   ocean-wind   a wind sea: JONSWAP, 10 m/s over 100 km, travelling 20 degrees right of
#                the view, cos-2s spreading, 512 waves from 0.1 m
#   ocean-swell  a swell of 1.2 m and 11 s travelling 30 degrees left of the view under a
#                younger wind sea (7 m/s over 30 km, 40 degrees right), 384 + 128 waves
# Both keep the view and the measurement look of the other shipped scenes
# (scripts/templates/plain.json: 640x360, a camera 2.5 m above the sea, the sun 12 degrees
# high straight ahead, light 1, no sky, no Fresnel; `sunglint ocean`'s own default is the
# sea as it looks, with a sky and Fresnel).
#
#   scripts/ocean-scenes.sh [path/to/sunglint] [output folder, default scenes/]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-$root/build/sunglint}
out=${2:-$root/scenes}
plain=(--template "$root/scripts/templates/plain.json")
"$bin" ocean -o "$out/ocean-wind.json" "${plain[@]}" --spectrum jonswap --wind-speed 10 --fetch 100 \
  --wind-direction 20 --spreading cos2s --waves 512 --wavelengths 0.1-1000 --seed 1
"$bin" ocean -o "$out/ocean-swell.json" "${plain[@]}" --spectrum jonswap --wind-speed 7 --fetch 30 \
  --wind-direction 40 --spreading donelan-banner --waves 384 --wavelengths 0.1-1000 \
  --swell-height 1.2 --swell-period 11 --swell-direction -30 --swell-spread 75 \
  --swell-waves 128 --seed 2
