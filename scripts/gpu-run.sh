#!/usr/bin/env bash
# Runs sunglint's programs on a bare GPU machine from the bundle of scripts/gpu-bundle.sh
# (docs/gpu.md): unpacks it outside the system folders, points the loader at it, finds the
# NVIDIA driver's EGL vendor file, prints the GL renderer, optionally starts Xvfb for the
# viewer's GLX window, then runs the commands and writes the log under $OUT.
#
#   scripts/gpu-run.sh [--bundle DIR] [--x] [--] [COMMAND]...
#
# Each COMMAND is a shell command line run from the repository's root, with the bundle's
# programs first on PATH (sunglint, gl_info, gl_test, window_test, ...) and
# SUNGLINT_REQUIRE_GL=1 (a GL test fails rather than skips). Without commands: gl_test, and
# window_test with --x. --x starts Xvfb (with Mesa's swrast_dri.so for its GLX) and sets
# DISPLAY; where the NVIDIA driver is present, __GLX_VENDOR_LIBRARY_NAME=nvidia renders the
# window on the GPU. $OUT (default .gpu-out/) receives gpu-run.log (everything) and
# summary.txt (exit code and seconds per command). Exits non-zero if any command failed.
# Works here too, on Mesa: `env -i PATH=/usr/bin:/bin bash scripts/gpu-run.sh --x`.
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bundle=$repo/.gpu
with_x=0
while [ $# -gt 0 ]; do
  case $1 in
    --bundle) bundle=$(cd "$2" && pwd); shift 2 ;;
    --x) with_x=1; shift ;;
    --) shift; break ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    -*) echo "gpu-run: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
commands=("$@")
if [ ${#commands[@]} -eq 0 ]; then
  commands=(gl_test)
  [ $with_x = 1 ] && commands+=(window_test)
fi

out=${OUT:-$repo/.gpu-out}
mkdir -p "$out"
log=$out/gpu-run.log
summary=$out/summary.txt
: >"$log"
: >"$summary"
say() { echo "gpu-run: $*" | tee -a "$log" >&2; }
die() { say "$*"; exit 1; }

[ -f "$bundle/engine.tar.xz" ] || die "$bundle/engine.tar.xz: no bundle (make it with scripts/gpu-bundle.sh and carry .gpu)"
root=${SG_GPU_ROOT:-/tmp/sunglint-gpu}
rm -rf "$root"
mkdir -p "$root"
# tar -J needs the xz program, which a bare image may lack; Python's tarfile reads xz too.
unpack() {
  if command -v xz >/dev/null 2>&1; then
    tar -C "$root" -xJf "$1"
  elif command -v python3 >/dev/null 2>&1; then
    python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$1" "$root"
  else
    say "neither xz nor python3 here"
    return 1
  fi
}
unpack "$bundle/engine.tar.xz" || die "cannot unpack $bundle/engine.tar.xz"
if [ $with_x = 1 ]; then
  [ -f "$bundle/x11.tar.xz" ] || die "--x: $bundle/x11.tar.xz missing (bundle made with --no-x)"
  unpack "$bundle/x11.tar.xz" || die "cannot unpack $bundle/x11.tar.xz"
fi
sed -n '1,8p' "$bundle/MANIFEST.txt" >>"$log"

# The loader: the bundle's libraries, the GL loaders, the NVIDIA driver's folders if any.
driver_dirs=""
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu/nvidia; do
  [ -d "$d" ] && driver_dirs="$driver_dirs:$d"
done
export LD_LIBRARY_PATH="$root/lib:$root/glvnd$driver_dirs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$root/bin:$PATH"
# libstdc++ and libgcc_s from the bundle only where the machine's are missing or older.
probe=$("$root/bin/gl_info" --no-such-option 2>&1 >/dev/null)
if grep -q "error while loading shared libraries\|version .GLIBCXX\|version .CXXABI\|version .GCC_" <<<"$probe"; then
  export LD_LIBRARY_PATH="$root/lib/compat:$LD_LIBRARY_PATH"
  say "using the bundle's libstdc++/libgcc_s (the machine's: ${probe%%$'\n'*})"
  probe=$("$root/bin/gl_info" --no-such-option 2>&1 >/dev/null)
  grep -q "error while loading shared libraries\|version .GLIBC" <<<"$probe" &&
    die "the programs do not load here: ${probe%%$'\n'*}"
fi

# The EGL vendor: glvnd reads /usr/share/glvnd/egl_vendor.d and /etc/glvnd/egl_vendor.d;
# NVIDIA's container image keeps its file under /usr/local/nvidia instead.
nvidia_json=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] &&
  ! ls /usr/share/glvnd/egl_vendor.d/*.json /etc/glvnd/egl_vendor.d/*.json >/dev/null 2>&1; then
  if [ -f "$nvidia_json" ]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia_json
    say "no EGL vendor file in the system folders: __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia_json"
  else
    say "no EGL vendor file found (no driver?): the GL programs will say so"
  fi
fi
nvidia=0
if ls /usr/local/nvidia/lib*/libGLX_nvidia.so.0 >/dev/null 2>&1 ||
  ldconfig -p 2>/dev/null | grep -q libGLX_nvidia.so.0; then
  nvidia=1
fi

# The test programs know the build machine's source and build folders (fixtures, outputs):
# make them exist here, the source folder as a link to this checkout.
src_dir=$(sed -n 's/^SG_SOURCE_DIR=//p' "$bundle/MANIFEST.txt")
bin_dir=$(sed -n 's/^SG_BINARY_DIR=//p' "$bundle/MANIFEST.txt")
if [ -n "$src_dir" ] && [ ! -e "$src_dir" ]; then
  if mkdir -p "$(dirname "$src_dir")" 2>/dev/null && ln -s "$repo" "$src_dir" 2>/dev/null; then
    say "linked $src_dir -> $repo (the tests' SG_SOURCE_DIR)"
  else
    say "cannot link $src_dir -> $repo: tests that read fixtures will not find them"
  fi
fi
[ -n "$bin_dir" ] && [ ! -e "$bin_dir" ] && mkdir -p "$bin_dir" 2>/dev/null

xvfb_pid=""
cleanup() { [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null; }
trap cleanup EXIT
if [ $with_x = 1 ]; then
  # Xvfb runs xkbcomp from /usr/bin (compiled in); a bare machine has none.
  if [ ! -x /usr/bin/xkbcomp ]; then
    cp "$root/bin/xkbcomp" /usr/bin/xkbcomp 2>/dev/null ||
      die "Xvfb needs /usr/bin/xkbcomp and it cannot be installed (not root?)"
    say "installed /usr/bin/xkbcomp from the bundle"
  fi
  fifo=$(mktemp -u)
  mkfifo "$fifo"
  LIBGL_DRIVERS_PATH=$root/dri "$root/bin/Xvfb" -displayfd 3 -screen 0 1920x1080x24 \
    -nolisten tcp -noreset -xkbdir "$root/share/X11/xkb" 3>"$fifo" >>"$log" 2>&1 &
  xvfb_pid=$!
  display=""
  read -r -t 30 display <"$fifo"
  rm -f "$fifo"
  [ -n "$display" ] || die "Xvfb did not start (its messages are in $log)"
  export DISPLAY=:$display
  # The window tests use this display rather than start their own Xvfb (testing/xvfb.h).
  export SUNGLINT_TEST_DISPLAY=$DISPLAY
  say "Xvfb on DISPLAY=$DISPLAY"
  if [ $nvidia = 1 ] && [ -z "${__GLX_VENDOR_LIBRARY_NAME:-}" ]; then
    export __GLX_VENDOR_LIBRARY_NAME=nvidia
    say "GLX through NVIDIA's vendor library: __GLX_VENDOR_LIBRARY_NAME=nvidia"
  fi
fi

export SUNGLINT_REQUIRE_GL=1
info_args=()
[ $with_x = 1 ] && info_args=(--window)
say "GL renderer:"
gl_info "${info_args[@]}" 2>&1 | tee -a "$log"
[ "${PIPESTATUS[0]}" = 0 ] || die "no OpenGL 4.5 context here (gl_info's message above)"

failed=0
cd "$repo" || exit 1
for k in "${!commands[@]}"; do
  cmd=${commands[$k]}
  say "[$((k + 1))/${#commands[@]}] $cmd"
  start=$(date +%s.%N)
  bash -c "$cmd" 2>&1 | tee -a "$log"
  rc=${PIPESTATUS[0]}
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  printf '%3d %8s s  %s\n' "$rc" "$seconds" "$cmd" >>"$summary"
  [ "$rc" = 0 ] || failed=1
done
echo "gpu-run: exit code, seconds, command:" >&2
cat "$summary" >&2
exit $failed
