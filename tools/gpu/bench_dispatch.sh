#!/bin/sh
# Fragment vs compute dispatch, and the compute work groups: per
# scene, the median of N renders (default 5) of the `render` time that
# `render -v` reports (the draw and the read-back, no context, link or
# write) at WxH (default 1280x720) and SPP samples (default 4: llvmpipe
# compiles machine code at the first draw, which one sample would not
# amortize), through the real binary. Prints a markdown table of ms.
#   tools/gpu/bench_dispatch.sh [build/marchstudio] [N] [WxH] [groups...]
#   groups: --compute-group values (WxH, or WxH/S for stripes of S group
#   rows); default 8x8. SCENES="seed terrain" limits the scenes; SPP=1.
set -eu
BIN=${1:-build/marchstudio}; N=${2:-5}; SIZE=${3:-1280x720}
shift $(( $# > 3 ? 3 : $# )) || true
GROUPS=${*:-8x8}
SPP=${SPP:-4}
SCENES=${SCENES:-$(for s in scenes/*.toml; do basename "$s" .toml; done)}
OUT=$(mktemp -d); trap 'rm -rf "$OUT"' EXIT
median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
run() {  # scene, extra flags...: median render ms
  s=$1; shift
  for i in $(seq "$N"); do
    "$BIN" render "scenes/$s.toml" --size "$SIZE" --spp "$SPP" -v -o "$OUT/x.png" "$@" 2>&1 >/dev/null |
      sed -n 's/.* render \([0-9.]*\) ms.*/\1/p' | grep . || echo fail
  done | median
}
printf '| scene | fragment |'; for g in $GROUPS; do printf ' compute %s |' "$g"; done; echo
printf '|---|---|'; for g in $GROUPS; do printf -- '---|'; done; echo
for s in $SCENES; do
  printf '| %s | %s |' "$s" "$(run "$s" --dispatch fragment)"
  for g in $GROUPS; do printf ' %s |' "$(run "$s" --dispatch compute --compute-group "$g")"; done; echo
done
