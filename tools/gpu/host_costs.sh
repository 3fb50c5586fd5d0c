#!/usr/bin/env bash
# Per-frame host costs (docs/gpu-bench.md#per-frame-host-costs):
# per scene, size and dispatch, `marchstudio bench --json`'s medians of the
# GPU timer, the wall time (draw + glFinish) and the host's submit time (the
# draw call returning), its glGetUniformLocation counts and its uniform
# sends (first frames, and per timed frame). A markdown table on stdout.
#   tools/gpu/host_costs.sh [path/to/marchstudio]
#   SCENES (default "seed stilllife"), SIZES (default "320x180 1280x720"),
#   DISPATCHES (default "fragment compute"), FRAMES (50), WARMUP (5);
#   any extra bench flags in BENCH_FLAGS (e.g. "--backend egl").
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
read -r -a scenes <<<"${SCENES:-seed stilllife}"
read -r -a sizes <<<"${SIZES:-320x180 1280x720}"
read -r -a dispatches <<<"${DISPATCHES:-fragment compute}"
read -r -a extra <<<"${BENCH_FLAGS:-}"
frames=${FRAMES:-50} warmup=${WARMUP:-5}
# shellcheck source=common.sh
source "$root/tools/gpu/common.sh"
r3() { awk -v x="$1" 'BEGIN { printf "%.3f", x }'; }
timer() { awk -v x="$1" 'BEGIN { if (x < 0.001) print "-"; else printf "%.3f", x }'; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| scene | size | dispatch | GPU timer ms median | wall ms median | submit ms median (p95) | wall - GPU ms | uniform lookups: first frames / later | uniforms sent: first frames / a frame |"
echo "|---|---|---|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  for size in "${sizes[@]}"; do
    for d in "${dispatches[@]}"; do
      "$bin" bench "$root/scenes/$s.toml" --size "$size" --frames "$frames" --warmup "$warmup" --dispatch "$d" \
        ${extra[@]+"${extra[@]}"} --json >"$tmp/out.json"
      f=($(fields "$tmp/out.json" /frame_ms/gpu/median /frame_ms/wall/median /frame_ms/submit/median \
        /frame_ms/submit/p95 /uniform_lookups/first_frames /uniform_lookups/later_frames \
        /uniform_sets/first_frames /uniform_sets/per_timed_frame))
      gap=$(awk -v g="${f[0]}" -v w="${f[1]}" 'BEGIN { if (g < 0.001) print "-"; else printf "%.3f", w - g }')
      echo "| $s | $size | $d | $(timer "${f[0]}") | $(r3 "${f[1]}") | $(r3 "${f[2]}") ($(r3 "${f[3]}")) | $gap | ${f[4]} / ${f[5]} | ${f[6]} / ${f[7]} |"
    done
  done
done
