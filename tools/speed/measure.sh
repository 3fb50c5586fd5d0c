#!/usr/bin/env bash
# Re-measures every figure in docs/speed-vs-error.md on this machine and
# regenerates the page: the full sweep grid of each scene at 640x360, the
# quick grid at 1280x720 (the issue's targets), then tools/speed/fill.py.
# About 11 minutes on 2 llvmpipe cores (2026-12-01). Times are process CPU time per frame
# (--time-by cpu): the steadiest clock on a shared machine (docs/speed-vs-error.md).
#
# Usage: tools/speed/measure.sh [path/to/marchstudio]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
[[ -x $bin ]] || { echo "measure.sh: no marchstudio binary at '$bin'" >&2; exit 2; }
cd "$root"
out=docs/images/speed
mkdir -p "$out/1280x720"
for s in seed stilllife columns; do
  echo "== $s: full grid, 640x360" >&2
  "$bin" sweep "scenes/$s.toml" --size 640x360 --grid full --time-by cpu -q -o "$out" >/dev/null
  echo "== $s: quick grid, 1280x720" >&2
  "$bin" sweep "scenes/$s.toml" --size 1280x720 --grid quick --time-by cpu -q -o "$out/1280x720" >/dev/null
done
python3 tools/speed/fill.py
