#!/usr/bin/env bash
# tools/gpu/device_run.sh on llvmpipe, tiny sizes: the script a GPU session
# runs once must not fail there for a reason llvmpipe could have shown.
# Every stage's file is written and well formed; a spent budget skips the
# stages left and exits 4.
#   tests/gpu/check_device_run.sh path/to/marchstudio
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "check_device_run.sh: $*" >&2; [[ -f $out/a/log.txt ]] && cat "$out/a/log.txt" >&2; exit 1; }
rows() { grep -c '^| [a-z]' "$1" | awk '{ print $1 - 1 }'; }  # table rows, less the header

env ALLOW_SOFTWARE=1 TARGET_SIZE=16x16 HOST_SIZES=16x16 FULL_SIZES=16x16 FULL_SCENES=seed FULL_PRESETS=fast \
  FRAMES=2 WARMUP=0 OUT="$out/a" "$root/tools/gpu/device_run.sh" "$bin" 2>/dev/null
rc=$?
(( rc == 0 )) || fail "exit $rc, not 0"
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

# A budget already spent: the stages are skipped, the exit is 4.
env ALLOW_SOFTWARE=1 BUDGET_S=1 OUT="$out/b" "$root/tools/gpu/device_run.sh" "$bin" 2>/dev/null
rc=$?
(( rc == 4 )) || fail "a spent budget exits $rc, not 4"
grep -q 'targets: skipped, the budget is spent' "$out/b/log.txt" || fail "log.txt does not say targets was skipped"
[[ ! -e $out/b/targets.md ]] || fail "targets.md written with no budget"
# Without ALLOW_SOFTWARE, llvmpipe is refused (exit 3) before any stage,
# so a table from the script is a GPU's. (Where EGL gives a GPU, skipped.)
if grep -q '"gl_renderer": "llvmpipe' "$out/a/info.txt"; then
  env -u ALLOW_SOFTWARE OUT="$out/c" "$root/tools/gpu/device_run.sh" "$bin" 2>/dev/null
  rc=$?
  (( rc == 3 )) || fail "llvmpipe without ALLOW_SOFTWARE exits $rc, not 3"
  [[ ! -e $out/c/targets.md && ! -e $out/c/targets.md.part ]] || fail "a stage ran on llvmpipe"
fi
echo "check_device_run.sh: ok"
