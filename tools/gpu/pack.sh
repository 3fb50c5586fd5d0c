#!/usr/bin/env bash
# Packs what a GPU session carries to the device machine into one folder
# (default .gpu/, which .gitignore ignores; docs/gpu-bench.md#gpu-figures):
#   marchstudio-gpubench   the lean bench (tools/gpu/CMakeLists.txt)
#   libtomlplusplus.so.3   its one library outside glibc and GL
#   libEGL.so.1, libGLdispatch.so.0
#                          glvnd's EGL loader: the GPU machine's image may
#                          have none (its driver brings only the vendor
#                          library, libEGL_nvidia)
#   glibc/                 this machine's glibc, loader first, and the C++
#                          runtime: the binary needs GLIBC_2.36 (Debian 12),
#                          and where the GPU machine's glibc is older,
#                          device_run.sh starts it through this loader
#                          instead (tools/gpu/launch.sh)
#
# Usage: tools/gpu/pack.sh [BINARY]
#   no BINARY: configures and builds build-gpu/marchstudio-gpubench first
#   DEST: the folder to fill (default .gpu); replaced whole, at the end
# Exit codes: 0 packed; 1 a build failed or a library was not found.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
dest=${DEST:-$root/.gpu}
bin=${1:-}
die() { echo "pack.sh: $*" >&2; exit 1; }

if [[ -z $bin ]]; then
  cmake -S "$root" -B "$root/build-gpu" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMARCH_GPU_BENCH=ON -DBUILD_TESTING=OFF
  cmake --build "$root/build-gpu" --target marchstudio-gpubench
  bin=$root/build-gpu/marchstudio-gpubench
fi
[[ -x $bin ]] || die "no binary at $bin"

deps=$(ldd "$bin") || die "ldd $bin failed"
# path SONAME: where ldd resolved SONAME for the binary (empty if not needed).
path() { awk -v n="$1" '$1 == n && $2 == "=>" { print $3 }' <<<"$deps"; }
libc=$(path libc.so.6)
loader=$(awk '$1 ~ /ld-linux-x86-64\.so\.2$/ { print $1 }' <<<"$deps")
[[ -n $libc && -n $loader ]] || die "ldd found no glibc for $bin"
libdir=$(dirname "$libc")
# Nothing beyond what is packed below (and the kernel's vDSO): a codec or
# GLFW linked in by mistake would fail only on the GPU machine.
extra=$(awk '$1 !~ /^(linux-vdso|libtomlplusplus|libEGL|libGLdispatch|libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s)\.so/ && $1 !~ /ld-linux-x86-64\.so\.2$/ { print $1 }' <<<"$deps" | tr '\n' ' ')
[[ -z $extra ]] || die "$bin needs libraries the pack does not carry: $extra"

tmp=$dest.tmp
rm -rf "$tmp"
mkdir -p "$tmp/glibc"
cp "$bin" "$tmp/marchstudio-gpubench"
for n in libtomlplusplus.so.3 libEGL.so.1 libGLdispatch.so.0; do
  p=$(path "$n")
  [[ -n $p ]] || die "$bin does not link $n (ldd: $(grep -F "$n" <<<"$deps" || echo none))"
  cp -L "$p" "$tmp/$n"
done
# One glibc, all of a piece: its loader and the libraries a GL vendor
# library may still name (libdl, libpthread and librt are stubs since 2.34).
cp -L "$loader" "$tmp/glibc/ld-linux-x86-64.so.2"
for n in libc.so.6 libm.so.6 libdl.so.2 libpthread.so.0 librt.so.1; do
  [[ -f $libdir/$n ]] || die "no $libdir/$n"
  cp -L "$libdir/$n" "$tmp/glibc/$n"
done
# The C++ runtime toml++ was built against goes with them: an image's own
# may be older than GLIBCXX needs (the binary itself links it statically).
for n in libstdc++.so.6 libgcc_s.so.1; do
  p=$(path "$n")
  [[ -z $p ]] || cp -L "$p" "$tmp/glibc/$n"
done
rm -rf "$dest"
mv "$tmp" "$dest"
echo "pack.sh: $dest: $(du -sh "$dest" | cut -f1), $(find "$dest" -type f | wc -l) files, glibc $(ldd --version | head -1 | awk '{ print $NF }')"
