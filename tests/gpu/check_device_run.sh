#!/usr/bin/env bash
# tools/gpu/device_run.sh on llvmpipe, tiny sizes: the script a GPU session
# runs once must not fail there for a reason llvmpipe could have shown.
# The binary runs as tools/gpu/pack.sh packs it; every stage's file is
# written and well formed; the packed glibc starts it too (launch.sh); a
# binary that does not start exits 5, a spent budget skips the stages left
# and exits 4.
#   tests/gpu/check_device_run.sh path/to/marchstudio
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "check_device_run.sh: $*" >&2; [[ -f $out/a/log.txt ]] && cat "$out/a/log.txt" >&2; exit 1; }
rows() { grep -c '^| [a-z]' "$1" | awk '{ print $1 - 1 }'; }  # table rows, less the header

# What a GPU session carries: the folder pack.sh fills.
DEST=$out/pack "$root/tools/gpu/pack.sh" "$bin" >/dev/null || fail "pack.sh failed"
for f in marchstudio-gpubench libtomlplusplus.so.3 libEGL.so.1 libGLdispatch.so.0 \
  glibc/ld-linux-x86-64.so.2 glibc/libc.so.6 glibc/libm.so.6; do
  [[ -s $out/pack/$f ]] || fail "pack.sh: no $f"
done
[[ ! -e $out/pack.tmp ]] || fail "pack.sh left its .tmp folder"
packed=$out/pack/marchstudio-gpubench

env ALLOW_SOFTWARE=1 TARGET_SIZE=16x16 HOST_SIZES=16x16 FULL_SIZES=16x16 FULL_SCENES=seed FULL_PRESETS=fast \
  FRAMES=2 WARMUP=0 OUT="$out/a" "$root/tools/gpu/device_run.sh" "$packed" 2>/dev/null
rc=$?
(( rc == 0 )) || fail "exit $rc, not 0"
grep -q '^launch: plain$' "$out/a/info.txt" || fail "info.txt: the packed binary did not start plain"
grep -q "^LD_LIBRARY_PATH: $out/pack" "$out/a/info.txt" || fail "info.txt: the packed folder is not first on the library path"
for f in info.txt targets.md host_costs.md auto.json full_16x16.md log.txt; do
  [[ -s $out/a/$f ]] || fail "no $f"
done
grep -qE '"gl_renderer": "[^"]+"' "$out/a/info.txt" || fail "info.txt names no GL renderer"
(( $(rows "$out/a/targets.md") == 3 )) || fail "targets.md: not 3 rows (seed, stilllife, columns)"
grep -q '| columns | balanced | 16x16 |' "$out/a/targets.md" || fail "targets.md: no columns row"
(( $(rows "$out/a/host_costs.md") == 4 )) || fail "host_costs.md: not 4 rows"
(( $(rows "$out/a/full_16x16.md") == 1 )) || fail "full_16x16.md: not 1 row"
/usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["settings"]["dispatch"] in ("fragment", "compute")' \
  "$out/a/auto.json" || fail "auto.json: no dispatch chosen"
ls "$out/a" | grep -q '\.part$' && fail "a .part file left by a run that succeeded"

# Through the packed glibc's loader, as on an image with an older glibc.
env ALLOW_SOFTWARE=1 GPU_LAUNCH=bundled TARGET_SIZE=16x16 HOST_SIZES=16x16 FULL_SIZES= \
  FRAMES=2 WARMUP=0 OUT="$out/d" "$root/tools/gpu/device_run.sh" "$packed" 2>/dev/null
rc=$?
(( rc == 0 )) || fail "through the packed glibc: exit $rc, not 0"
grep -q '^launch: through the packed glibc$' "$out/d/info.txt" || fail "info.txt does not say the packed glibc started it"
(( $(rows "$out/d/targets.md") == 3 )) || fail "through the packed glibc: targets.md not 3 rows"
ls "$out/d" | grep -q '^full_' && fail "FULL_SIZES empty still ran a full table"

# A binary that does not start here (an image's glibc too old, nothing
# packed to start it with): exit 5 before any stage, and log.txt says why.
mkdir -p "$out/old"
cat >"$out/old/marchstudio-gpubench" <<'EOS'
#!/bin/sh
echo "marchstudio-gpubench: /lib/x86_64-linux-gnu/libc.so.6: version \`GLIBC_2.36' not found" >&2
exit 1
EOS
chmod +x "$out/old/marchstudio-gpubench"
env ALLOW_SOFTWARE=1 OUT="$out/e" "$root/tools/gpu/device_run.sh" "$out/old/marchstudio-gpubench" 2>/dev/null
rc=$?
(( rc == 5 )) || fail "a binary that does not start exits $rc, not 5"
grep -q 'does not start.*GLIBC_2.36.*no .*ld-linux-x86-64.so.2' "$out/e/log.txt" ||
  fail "log.txt does not say why the binary does not start: $(cat "$out/e/log.txt")"
[[ ! -e $out/e/targets.md && ! -e $out/e/probe.json ]] || fail "a run went on with a binary that does not start"

# The driver's mount as NVIDIA's container runtime lays it out: its
# libraries follow the packed folder, its EGL vendor file is named (this
# machine's glvnd folders have no NVIDIA vendor of their own).
mkdir -p "$out/nv/lib64" "$out/nv/share/glvnd/egl_vendor.d"
echo '{}' >"$out/nv/share/glvnd/egl_vendor.d/10_nvidia.json"
env=$(GPU_NVIDIA_ROOT=$out/nv LD_LIBRARY_PATH=/x __EGL_VENDOR_LIBRARY_FILENAMES=/pin.json bash -c \
  'source "$1"; gpu_environment /packed; echo "$LD_LIBRARY_PATH $__EGL_VENDOR_LIBRARY_FILENAMES $MARCH_GPU_ENV"' \
  _ "$root/tools/gpu/launch.sh")
if ! ls /usr/share/glvnd/egl_vendor.d/*nvidia*.json /etc/glvnd/egl_vendor.d/*nvidia*.json >/dev/null 2>&1; then
  [[ $env == "/packed:/x:$out/nv/lib64 $out/nv/share/glvnd/egl_vendor.d/10_nvidia.json 1" ]] ||
    fail "gpu_environment with a mounted driver: '$env'"
fi

# No EGL vendor to load (GPU_EGL_VENDOR names one that is not there): the
# probe fails, exit 3, and log.txt says where the vendors and libraries are.
env ALLOW_SOFTWARE=1 GPU_EGL_VENDOR=$out/none.json OUT="$out/f" "$root/tools/gpu/device_run.sh" "$packed" 2>/dev/null
rc=$?
(( rc == 3 )) || fail "no EGL vendor exits $rc, not 3"
grep -q 'probe: bench failed' "$out/f/log.txt" && grep -q 'EGL libraries the loader cache knows' "$out/f/log.txt" ||
  fail "log.txt has no diagnosis of the failed probe: $(cat "$out/f/log.txt")"

# A budget already spent: the stages are skipped, the exit is 4.
env ALLOW_SOFTWARE=1 BUDGET_S=1 OUT="$out/b" "$root/tools/gpu/device_run.sh" "$packed" 2>/dev/null
rc=$?
(( rc == 4 )) || fail "a spent budget exits $rc, not 4"
grep -q 'targets: skipped, the budget is spent' "$out/b/log.txt" || fail "log.txt does not say targets was skipped"
[[ ! -e $out/b/targets.md ]] || fail "targets.md written with no budget"
# Without ALLOW_SOFTWARE, llvmpipe is refused (exit 3) before any stage,
# so a table from the script is a GPU's. (Where EGL gives a GPU, skipped.)
if grep -q '"gl_renderer": "llvmpipe' "$out/a/info.txt"; then
  env -u ALLOW_SOFTWARE OUT="$out/c" "$root/tools/gpu/device_run.sh" "$packed" 2>/dev/null
  rc=$?
  (( rc == 3 )) || fail "llvmpipe without ALLOW_SOFTWARE exits $rc, not 3"
  [[ ! -e $out/c/targets.md && ! -e $out/c/targets.md.part ]] || fail "a stage ran on llvmpipe"
fi
echo "check_device_run.sh: ok"
