#!/usr/bin/env bash
# Checks here, before a GPU machine is spent on it, that the bundle of scripts/gpu-bundle.sh
# is self-sufficient: builds a bare root like the GPU machine's (glibc, libstdc++, bash and
# the tools scripts/gpu-run.sh uses; no X, no GL, no Mesa in the system folders), puts
# Mesa in it where the NVIDIA container keeps its driver (/usr/local/nvidia/lib64, and its
# EGL vendor file at /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json, pointing at
# Mesa's libEGL_mesa) as the stand-in driver, with only the driver's own libraries (those
# the bundle carries come from the bundle), copies the checkout and .gpu into it, and runs
# scripts/gpu-run.sh there under chroot. Needs root (chroot, mount). Logs in .gpu-out/bare/.
#
#   sudo scripts/gpu-bare-check.sh [--no-libstdcxx] [--no-xz] [--x] [-- COMMAND...]
#
# The arguments after the first two options go to gpu-run.sh. --no-libstdcxx leaves
# libstdc++ and libgcc_s out of the root, so that gpu-run.sh must take the bundle's
# (lib/compat); --no-xz leaves the xz program out and puts python3 in, which then unpacks.
set -euo pipefail
no_cxx=0
no_xz=0
while [ $# -gt 0 ]; do
  case $1 in
    --no-libstdcxx) no_cxx=1; shift ;;
    --no-xz) no_xz=1; shift ;;
    *) break ;;
  esac
done
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ "$(id -u)" = 0 ] || { echo "gpu-bare-check: needs root (chroot, mount)" >&2; exit 1; }
[ -f "$repo/.gpu/engine.tar.xz" ] || { echo "gpu-bare-check: no .gpu bundle (scripts/gpu-bundle.sh)" >&2; exit 1; }

root=$(mktemp -d /tmp/sg-bare.XXXXXX)
mounts=()
cleanup() {
  local m
  for ((k = ${#mounts[@]} - 1; k >= 0; k--)); do umount "${mounts[$k]}" 2>/dev/null || true; done
  if grep -q " $root" /proc/mounts; then
    echo "gpu-bare-check: $root still has mounts; not removing it" >&2
  else
    rm -rf "$root"
  fi
}
[ -n "${SG_BARE_KEEP:-}" ] || trap cleanup EXIT

lib=/usr/lib/x86_64-linux-gnu
mkdir -p "$root/usr/bin" "$root/usr/sbin" "$root$lib/dri" "$root/usr/lib64" \
  "$root/usr/local/nvidia/lib64" "$root/usr/local/nvidia/share/glvnd/egl_vendor.d" \
  "$root/tmp" "$root/proc" "$root/dev/shm" "$root/etc" "$root/out" "$root/repo"
chmod 1777 "$root/tmp"
ln -s usr/bin "$root/bin"
ln -s usr/sbin "$root/sbin"
ln -s usr/lib "$root/lib"
ln -s usr/lib64 "$root/lib64"

# Copies files to the same path in the root (following links), with the libraries they need
# from glibc and libstdc++ (the GPU machine has those).
system_libs='^(ld-linux|libc\.so|libm\.so|libmvec|libdl\.so|libpthread|librt\.so|libutil\.so|libresolv|libstdc\+\+|libgcc_s|libtinfo|libpcre2-8|libselinux|libacl|libattr|libgmp|libcrypto|liblzma|libz\.so|libbz2|libzstd|libmd\.so|libcap)'
copy_system() {
  local f l
  for f in "$@"; do
    mkdir -p "$root$(dirname "$f")"
    cp -L "$f" "$root$f"
    for l in $(ldd "$f" 2>/dev/null | awk '$2 == "=>" && $3 ~ /^\// { print $3 } $1 ~ /^\// { print $1 }'); do
      [[ $(basename "$l") =~ $system_libs ]] || continue
      [ -e "$root$lib/$(basename "$l")" ] || cp -L "$l" "$root$lib/"
    done
  done
}
tools=(bash env cat cp mkdir rm ln ls sed awk grep tar xz mktemp mkfifo date dirname basename
  tee sort head tail cut tr sleep stat du find wc id uname realpath)
paths=()
if [ $no_xz = 1 ]; then
  # Debian's python3 and its standard library (no site packages).
  tools=("${tools[@]/#xz/}")
  py=/usr/bin/python3
  stdlib=$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["stdlib"])')
  mkdir -p "$root$stdlib"
  (cd "$stdlib" && tar --exclude=./site-packages --exclude=./dist-packages --exclude=./test -cf - .) |
    tar -C "$root$stdlib" -xf -
  paths+=("$(readlink -f "$py")" "$("$py" -c 'import _lzma; print(_lzma.__file__)')")
  cp -L "$(ldconfig -p | awk '$1 == "liblzma.so.5" { print $NF; exit }')" "$root$lib/"
  ln -s "$(basename "$(readlink -f "$py")")" "$root/usr/bin/python3"
fi
for t in "${tools[@]}"; do [ -n "$t" ] && paths+=("$(readlink -f "$(type -P "$t")")"); done
copy_system "${paths[@]}"
for t in "${tools[@]}"; do
  [ -n "$t" ] || continue
  [ -e "$root/usr/bin/$t" ] || ln -s "$(readlink -f "$(type -P "$t")")" "$root/usr/bin/$t"
done
ln -sf bash "$root/usr/bin/sh"
copy_system /sbin/ldconfig
cp -L /lib64/ld-linux-x86-64.so.2 "$root/usr/lib64/"
for l in libc.so.6 libm.so.6 libdl.so.2 libpthread.so.0 librt.so.1 libstdc++.so.6 libgcc_s.so.1; do
  cp -L "$lib/$l" "$root$lib/"
done
[ $no_cxx = 1 ] && rm -f "$root$lib/libstdc++.so.6" "$root$lib/libgcc_s.so.1"
echo "root:x:0:0:root:/tmp:/bin/bash" >"$root/etc/passwd"

# The stand-in driver: Mesa's vendor libraries and DRI driver with their own libraries,
# except glibc's, libstdc++'s and those the bundle carries.
# (The viewer's x11 part is unpacked only with --x, so it does not count.)
bundle_libs=$(tar -tJf "$repo/.gpu/engine.tar.xz" | sed -n 's|^\./lib/\(compat/\)\{0,1\}||p')
driver=("$lib/libEGL_mesa.so.0" "$lib/libGLX_mesa.so.0" "$lib/dri/swrast_dri.so")
for f in "${driver[@]}"; do
  case $f in
    */dri/*) cp -L "$f" "$root$lib/dri/" ;;
    *) cp -L "$f" "$root/usr/local/nvidia/lib64/" ;;
  esac
  for l in $(ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }'); do
    n=$(basename "$l")
    [[ $n =~ ^(libc\.so|libm\.so|libdl\.so|libpthread|librt\.so|ld-linux|libstdc\+\+|libgcc_s|libGL|libGLX\.so|libGLdispatch|libEGL\.so|libOpenGL) ]] && continue
    grep -qx "$n" <<<"$bundle_libs" && continue
    [ -e "$root/usr/local/nvidia/lib64/$n" ] || cp -L "$l" "$root/usr/local/nvidia/lib64/"
  done
done
echo '{"file_format_version": "1.0.0", "ICD": {"library_path": "libEGL_mesa.so.0"}}' \
  >"$root/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json"
# The NVIDIA image lists its driver folder for the loader; so does this root.
echo /usr/local/nvidia/lib64 >"$root/etc/ld.so.conf"
chroot "$root" /sbin/ldconfig

# The checkout as the tool sends it (tracked and untracked-not-ignored files) and the bundle.
(cd "$repo" && git ls-files -co --exclude-standard -z | tar --null -T - -cf -) | tar -C "$root/repo" -xf -
cp -a "$repo/.gpu" "$root/repo/.gpu"

size=$(du -sh "$root" | cut -f1)
mount -t proc proc "$root/proc" && mounts+=("$root/proc")
for d in null zero random urandom; do
  touch "$root/dev/$d"
  mount --bind "/dev/$d" "$root/dev/$d" && mounts+=("$root/dev/$d")
done
mount -t tmpfs tmpfs "$root/dev/shm" && mounts+=("$root/dev/shm")

echo "gpu-bare-check: bare root $root ($size); running gpu-run.sh $*" >&2
rc=0
chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/tmp OUT=/out \
  bash /repo/scripts/gpu-run.sh "$@" || rc=$?
mkdir -p "$repo/.gpu-out/bare"
cp "$root"/out/* "$repo/.gpu-out/bare/" 2>/dev/null || true
echo "gpu-bare-check: gpu-run.sh exited $rc; logs in .gpu-out/bare/" >&2
exit $rc
