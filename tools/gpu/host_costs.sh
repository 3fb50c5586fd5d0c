#!/usr/bin/env bash
# Per-frame host costs (issue 18 item 5, docs/gpu.md#per-frame-host-costs):
# per scene, size and dispatch, `marchstudio bench --json`'s medians of the
# GPU timer, the wall time (draw + glFinish) and the host's submit time (the
# draw call returning), and its glGetUniformLocation counts. A markdown table
# on stdout.
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
echo "| scene | size | dispatch | GPU timer ms median | wall ms median | submit ms median (p95) | wall - GPU ms | uniform lookups: first frames / later |"
echo "|---|---|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  for size in "${sizes[@]}"; do
    for d in "${dispatches[@]}"; do
      "$bin" bench "$root/scenes/$s.toml" --size "$size" --frames "$frames" --warmup "$warmup" --dispatch "$d" \
        ${extra[@]+"${extra[@]}"} --json |
        jq -r --arg s "$s" --arg size "$size" --arg d "$d" '.frame_ms as $f | .uniform_lookups as $u |
          "| \($s) | \($size) | \($d) | \(if $f.gpu.median < 0.001 then "-" else ($f.gpu.median * 1000 | round / 1000) end) | \($f.wall.median * 1000 | round / 1000) | \($f.submit.median * 1000 | round / 1000) (\($f.submit.p95 * 1000 | round / 1000)) | \(if $f.gpu.median < 0.001 then "-" else (($f.wall.median - $f.gpu.median) * 1000 | round / 1000) end) | \($u.first_frames) / \($u.later_frames) |"'
    done
  done
done
