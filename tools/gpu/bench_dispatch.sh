#!/bin/sh
# Fragment vs compute dispatch per shipped scene (issue 18): the median wall
# time of N renders of each (default 5) at WxH (default 1280x720), spp 1,
# through the real binary. On llvmpipe this is the frame's CPU work plus a
# constant start-up; the difference between the columns is the dispatch's.
#   tools/gpu/bench_dispatch.sh [build/marchstudio] [N] [WxH] [groups...]
set -eu
BIN=${1:-build/marchstudio}; N=${2:-5}; SIZE=${3:-1280x720}
shift $(( $# > 3 ? 3 : $# )) || true
GROUPS=${*:-8x8}
OUT=$(mktemp -d); trap 'rm -rf "$OUT"' EXIT
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
run() {  # scene, extra flags...: median seconds
  s=$1; shift
  for i in $(seq "$N"); do
    t0=$(date +%s.%N); "$BIN" render "$s" --size "$SIZE" --spp 1 -o "$OUT/x.png" "$@" >/dev/null 2>&1 || { echo fail; return; }
    t1=$(date +%s.%N); echo "$t1 - $t0" | bc
  done | median
}
printf '%-10s %10s' scene fragment; for g in $GROUPS; do printf ' %10s' "c$g"; done; echo
for s in scenes/*.toml; do
  grep -q environment "$s" && continue  # texture inputs: compute refuses them for now
  printf '%-10s %10s' "$(basename "$s" .toml)" "$(run "$s" --dispatch fragment)"
  for g in $GROUPS; do printf ' %10s' "$(run "$s" --dispatch compute --compute-group "$g")"; done; echo
done
