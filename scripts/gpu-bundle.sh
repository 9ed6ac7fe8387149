#!/usr/bin/env bash
# Gathers into .gpu/ (ignored by git) what a run of sunglint on a bare GPU machine needs:
# a machine with the NVIDIA driver and glibc but no Debian packages and no network, reached
# with the working tree and a few carried folders (docs/gpu.md). scripts/gpu-run.sh unpacks
# it there and runs commands.
#
#   scripts/gpu-bundle.sh [--build DIR] [--out DIR] [--no-x] [--fast] [--bin FILE]...
#
# (--fast: quicker, larger compression, for trying the scripts out here.)
# .gpu/engine.tar.xz  bin/: the programs, stripped (sunglint, tools/gl_info, the GL tests,
#                     each --bin FILE, relative to the build folder or absolute);
#                     lib/: the shared libraries they need (ldd, plus those GLFW opens at run
#                     time) except glibc's, the GL loaders' and the driver's;
#                     lib/compat/: libstdc++ and libgcc_s, used only where the machine's are
#                     older; glvnd/: the GL loaders (libEGL, libGL, libGLX, libOpenGL,
#                     libGLdispatch), from the Debian packages downloaded as .deb files.
# .gpu/x11.tar.xz     (unless --no-x) the viewer's display: Xvfb and xkbcomp, Mesa's
#                     swrast_dri.so (Xvfb's GLX needs it), their libraries, the XKB data.
# .gpu/MANIFEST.txt   what is in it, from which build and packages, the sizes.
#
# The tool that reaches the GPU machine carries at most 64 MiB, working tree included: the
# script fails when the tree plus the bundle would exceed that.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$repo/build
out=$repo/.gpu
with_x=1
fast=0
extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$(cd "$2" && pwd); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --no-x) with_x=0; shift ;;
    --fast) fast=1; shift ;;
    --bin) extra+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "gpu-bundle: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
limit=$((64 * 1024 * 1024))
die() { echo "gpu-bundle: $*" >&2; exit 1; }

[ -f "$build/CMakeCache.txt" ] || die "$build: not a configured build folder (--build DIR)"
programs=("$build/sunglint" "$build/tools/gl_info" "$build/tests/gl_test" "$build/tests/window_test")
for b in "${extra[@]}"; do
  case $b in /*) programs+=("$b") ;; *) programs+=("$build/$b") ;; esac
done
for p in "${programs[@]}"; do
  [ -x "$p" ] || die "$p: no such program (build it first: cmake --build $build)"
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/engine/bin" "$stage/engine/lib/compat" "$stage/engine/glvnd" \
  "$stage/x11/bin" "$stage/x11/lib" "$stage/x11/dri" "$stage/x11/share/X11"

# Libraries that the GPU machine has or that come from elsewhere in the bundle: glibc, the GL
# loaders (glvnd/, from the packages) and vendor libraries (the NVIDIA driver's, or Mesa's).
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libmvec|libdl\.so|libpthread|librt\.so|libutil\.so|libresolv|libanl|libnss_|libBrokenLocale|libGL\.so|libGLX\.so|libGLX_|libEGL\.so|libEGL_|libOpenGL|libGLdispatch|libGLES|libnvidia-|libcuda)'
compat='^(libstdc\+\+\.so|libgcc_s\.so)'

# The resolved paths of everything `ldd` lists for the files, one per line.
ldd_paths() {
  for f in "$@"; do
    ldd "$f" 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// { print $3 }
                                $1 ~ /^\// { print $1 }'
  done | sort -u
}

# Copies the libraries of files $2... into folder $1 (compat ones into engine's lib/compat),
# except those in skip and those already in the folders named by $EXISTING.
copy_libs() {
  local dest=$1
  shift
  local lib name
  for lib in $(ldd_paths "$@"); do
    name=$(basename "$lib")
    [[ $name =~ $skip ]] && continue
    if [[ $name =~ $compat ]]; then
      [ -e "$stage/engine/lib/compat/$name" ] || cp -L "$lib" "$stage/engine/lib/compat/$name"
      continue
    fi
    local seen=0 d
    for d in ${EXISTING:-} "$dest"; do [ -e "$d/$name" ] && seen=1; done
    [ $seen = 1 ] || cp -L "$lib" "$dest/$name"
  done
}

# Finds a library by soname in the loader's cache.
find_lib() {
  ldconfig -p | awk -v n="$1" '$1 == n && /x86-64/ { print $NF; exit }'
}

echo "gpu-bundle: programs" >&2
for p in "${programs[@]}"; do
  strip --strip-unneeded -o "$stage/engine/bin/$(basename "$p")" "$p"
done
# GLFW opens its X11 libraries at run time; ldd does not see them.
glfw_dlopen=()
for so in libX11-xcb.so.1 libXcursor.so.1 libXrandr.so.2 libXinerama.so.1 libXi.so.6 \
  libXext.so.6 libXxf86vm.so.1 libXrender.so.1; do
  path=$(find_lib "$so")
  [ -n "$path" ] || die "$so not found (the viewer's window needs it: libglfw3's dependencies)"
  glfw_dlopen+=("$path")
done
copy_libs "$stage/engine/lib" "${programs[@]}" "${glfw_dlopen[@]}"
for path in "${glfw_dlopen[@]}"; do cp -L "$path" "$stage/engine/lib/"; done

echo "gpu-bundle: GL loaders (glvnd packages)" >&2
debs=$build/gpu-debs
mkdir -p "$debs"
glvnd_pkgs=(libglvnd0 libegl1 libopengl0 libgl1 libglx0)
missing=()
for pkg in "${glvnd_pkgs[@]}"; do
  ls "$debs/${pkg}_"*_amd64.deb >/dev/null 2>&1 || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
  (cd "$debs" && apt-get download -o APT::Architecture=amd64 "${missing[@]/%/:amd64}") >&2 ||
    die "apt-get download ${missing[*]} failed (needs the network and apt lists: apt-get update)"
fi
for pkg in "${glvnd_pkgs[@]}"; do
  deb=$(ls "$debs/${pkg}_"*_amd64.deb | sort -V | tail -1)
  dpkg-deb -x "$deb" "$stage/deb"
  echo "$(basename "$deb")" >>"$stage/debs.txt"
done
cp -a "$stage/deb/usr/lib/x86_64-linux-gnu/"lib*.so.* "$stage/engine/glvnd/"

# The viewer's part depends only on the installed packages and on which libraries the engine
# part already carries: it is cached (the compression takes minutes) under that key.
x_pkgs=(xvfb x11-xkb-utils xkb-data libgl1-mesa-dri libllvm15)
if [ $with_x = 1 ]; then
  x_key=$({ for pkg in "${x_pkgs[@]}"; do dpkg-query -W -f='${Package} ${Version}\n' "$pkg" 2>/dev/null || echo "$pkg ?"; done
    (cd "$stage/engine/lib" && ls -R); echo "$fast"; } | sha256sum | cut -c1-16)
  x_cache=$debs/x11-$x_key.tar.xz
  echo "$(for pkg in "${x_pkgs[@]}"; do dpkg-query -W -f='${Package}_${Version} ' "$pkg" 2>/dev/null; done)" >>"$stage/debs.txt"
fi
if [ $with_x = 1 ] && [ ! -f "$x_cache" ]; then
  echo "gpu-bundle: Xvfb, xkbcomp, Mesa's swrast_dri.so, XKB data" >&2
  xvfb=$(command -v Xvfb) || die "Xvfb not installed (Debian package xvfb)"
  xkbcomp=$(command -v xkbcomp) || die "xkbcomp not installed (Debian package x11-xkb-utils)"
  dri=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
  [ -f "$dri" ] || die "$dri not installed (Debian package libgl1-mesa-dri)"
  [ -d /usr/share/X11/xkb ] || die "/usr/share/X11/xkb not installed (Debian package xkb-data)"
  cp -L "$xvfb" "$stage/x11/bin/Xvfb"
  cp -L "$xkbcomp" "$stage/x11/bin/xkbcomp"
  cp -L "$dri" "$stage/x11/dri/swrast_dri.so"
  EXISTING="$stage/engine/lib $stage/engine/lib/compat" \
    copy_libs "$stage/x11/lib" "$xvfb" "$xkbcomp" "$dri"
  cp -a /usr/share/X11/xkb "$stage/x11/share/X11/xkb"
fi

# Strip the libraries too (most Debian ones are; a few keep symbol tables).
find "$stage/engine" "$stage/x11" -type f -name '*.so*' -exec strip --strip-unneeded {} + 2>/dev/null || true

echo "gpu-bundle: compressing" >&2
rm -rf "$out"
mkdir -p "$out"
xzopts=(-T1 --x86 --lzma2=preset=9e,dict=64MiB)
[ $fast = 1 ] && xzopts=(-T2 -1)
pack() { tar -C "$1" --sort=name --owner=0 --group=0 -cf - . | xz "${xzopts[@]}"; }
pack "$stage/engine" >"$out/engine.tar.xz"
if [ $with_x = 1 ]; then
  if [ ! -f "$x_cache" ]; then
    pack "$stage/x11" >"$x_cache.tmp"
    mv "$x_cache.tmp" "$x_cache"
  else
    echo "gpu-bundle: Xvfb and Mesa's pieces from the cache ($x_cache)" >&2
  fi
  cp "$x_cache" "$out/x11.tar.xz"
fi

source_dir=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
{
  echo "# sunglint GPU bundle (scripts/gpu-bundle.sh); unpacked and run by scripts/gpu-run.sh"
  echo "made: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -n)"
  echo "commit: $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?')$(git -C "$repo" diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"
  echo "build: $build ($build_type)"
  echo "SG_SOURCE_DIR=$source_dir"
  echo "SG_BINARY_DIR=$build"
  echo "packages: $(tr '\n' ' ' <"$stage/debs.txt")"
  echo "x11: $([ $with_x = 1 ] && echo yes || echo no)"
  echo
  echo "engine.tar.xz:"
  (cd "$stage/engine" && find . -type f -printf '  %10s %p\n' | sort -k2)
  if [ $with_x = 1 ]; then
    echo "x11.tar.xz (files in bin/, dri/, lib/; the XKB data in share/):"
    tar -tvJf "$out/x11.tar.xz" | awk '$1 !~ /^d/ && $6 !~ /share/ { printf "  %10s %s\n", $3, $6 }'
  fi
} >"$out/MANIFEST.txt"

bundle=$(du -cb "$out"/* | tail -1 | cut -f1)
tree=$(cd "$repo" && git ls-files -co --exclude-standard -z | du -cb --files0-from=- 2>/dev/null | tail -1 | cut -f1)
total=$((bundle + tree))
mib() { awk -v b="$1" 'BEGIN { printf "%.1f MiB", b / 1048576 }'; }
{
  echo
  echo "sizes: bundle $(mib "$bundle") ($(for f in "$out"/*.tar.xz; do printf '%s %s; ' "$(basename "$f")" "$(mib "$(stat -c %s "$f")")"; done)), working tree $(mib "$tree"), together $(mib "$total") of the 64 MiB a run carries"
} | tee -a "$out/MANIFEST.txt" >&2
if [ $total -gt $limit ]; then
  [ $fast = 1 ] && echo "gpu-bundle: over 64 MiB with --fast; without it the bundle is smaller" >&2
  [ $fast = 1 ] || die "the working tree and the bundle exceed 64 MiB: carry less (--no-x for runs without the viewer)"
fi
echo "gpu-bundle: wrote $out (carry it: \"carry\": [\"$(realpath --relative-to="$repo" "$out")\"])" >&2
