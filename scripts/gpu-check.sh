#!/usr/bin/env bash
# The GPU engine's one prepared run on a bare GPU machine (docs/gpu.md, docs/benchmarks.md):
# the GL tests and the benchmark of the figures, in one command of a few minutes.
#
#   scripts/gpu-check.sh prepare [--build DIR]   here: the bundle, with the GL engine's tests
#   scripts/gpu-check.sh run [--quick]           there (the device tool, carry [".gpu"]):
#
# `run` calls scripts/gpu-run.sh with, in order: gl_test and gl_engine_test (the GL layer,
# and every GL method against the CPU engine, SUNGLINT_REQUIRE_GL=1); `sunglint bench
# --engine gl` at 1920x1080 on the four shared scenes for point, staa --footprint none and
# staa (GPU timer, median of 5 after a warm-up, ratio to point); and the wall time of a
# 1920x1080 reference at 16x16x8 on the GL engine (`render --engine gl`, read-back and the
# EXR write included). --quick: 640x360 and a 4x4x4 reference, for trying it out here. The
# path tables (67 MB, over the tool's 64 MiB) are generated there on the first staa frame
# and announced. Everything lands in $OUT/ (gpu-run.log, summary.txt, bench.md).
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mode=${1:-}
shift || true
case $mode in
  prepare)
    build=$repo/build
    [ "${1:-}" = --build ] && build=$2
    exec bash "$repo/scripts/gpu-bundle.sh" --build "$build" --no-x --bin tests/gl_engine_test
    ;;
  run)
    w=1920 h=1080 ref=16x16x8
    [ "${1:-}" = --quick ] && w=640 h=360 ref=4x4x4
    out=${OUT:-$repo/.gpu-out}
    mkdir -p "$out"
    scenes="scenes/simple.json scenes/smooth.json scenes/medium.json scenes/high.json"
    exec bash "$repo/scripts/gpu-run.sh" -- gl_test gl_engine_test \
      "sunglint bench $scenes --engine gl --methods 'point,staa --footprint none,staa' --width $w --height $h --repeat 5 | tee $out/bench.md" \
      "time sunglint render scenes/medium.json -m reference --samples $ref --engine gl --width $w --height $h -o $out/reference.exr"
    ;;
  *)
    sed -n '2,15p' "$0"
    exit 2
    ;;
esac
