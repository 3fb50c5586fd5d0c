#!/usr/bin/env bash
# The GPU table for docs/speed-vs-error.md: `marchstudio bench --json` for
# the textbook baseline and the fast / balanced / reference presets, every
# shipped scene, at 1280x720 through EGL's device platform (the NVIDIA
# driver), printed as one markdown table on stdout. Progress and warnings go
# to stderr, so `tools/gpu/bench_gpu.sh > gpu.md` keeps only the table.
#
# Usage: tools/gpu/bench_gpu.sh [path/to/marchstudio]
#   The binary defaults to $MARCHSTUDIO, else build/marchstudio, else any
#   build*/marchstudio in the repository (a carried build).
# Environment:
#   FRAMES (default 60) and WARMUP (default 10): bench's --frames / --warmup
#   SIZE (default 1280x720)
#   SCENES (default: every scenes/*.toml), e.g. SCENES="seed stilllife"
#   ALLOW_SOFTWARE=1: run even when EGL gives a software renderer (llvmpipe)
#   SWEEP_DIR=DIR: also run `marchstudio sweep` (quick grid, same size) per
#     scene and leave its CSV, JSON and plot in DIR
# Exit codes: 0 ok; 2 no binary or no scenes; 3 no GPU behind EGL (unless
# ALLOW_SOFTWARE=1) or a bench run failed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-${MARCHSTUDIO:-}}
if [[ -z $bin ]]; then
  for candidate in "$root/build/marchstudio" "$root"/build*/marchstudio; do
    if [[ -x $candidate ]]; then bin=$candidate; break; fi
  done
fi
if [[ -z $bin || ! -x $bin ]]; then
  echo "bench_gpu.sh: no marchstudio binary (build it, pass its path, or set MARCHSTUDIO)" >&2
  exit 2
fi
frames=${FRAMES:-60}
warmup=${WARMUP:-10}
size=${SIZE:-1280x720}
presets=(textbook fast balanced reference)

# Let glvnd pick the GPU's EGL vendor: undo what the llvmpipe scripts pin.
unset __EGL_VENDOR_LIBRARY_FILENAMES LIBGL_ALWAYS_SOFTWARE GALLIUM_DRIVER || true

if [[ -n ${SCENES:-} ]]; then
  read -r -a names <<<"$SCENES"
else
  names=()
  for f in "$root"/scenes/*.toml; do names+=("$(basename "$f" .toml)"); done
fi
if (( ${#names[@]} == 0 )); then
  echo "bench_gpu.sh: no scenes" >&2
  exit 2
fi

# One field of bench's JSON by JSON pointer (/frame_ms/gpu/median): jq if
# there is one, else python3.
field() {
  local json=$1 pointer=$2
  if command -v jq >/dev/null 2>&1; then
    jq -r "getpath(\"$pointer\" | ltrimstr(\"/\") | split(\"/\"))" <<<"$json"
  else
    python3 -c 'import json, sys
v = json.loads(sys.stdin.read())
for k in sys.argv[1].strip("/").split("/"):
    v = v[k]
print(v)' "$pointer" <<<"$json"
  fi
}
fmt() { awk -v x="$1" -v f="$2" 'BEGIN { printf f, x }'; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A gpu
rows=()
renderer="" vendor="" version="" backend=""
for name in "${names[@]}"; do
  scene=$root/scenes/$name.toml
  for preset in "${presets[@]}"; do
    echo "bench_gpu.sh: $name $preset" >&2
    if ! "$bin" bench "$scene" --preset "$preset" --size "$size" --frames "$frames" --warmup "$warmup" \
        --backend egl --json >"$tmp/out.json" 2>"$tmp/err.txt"; then
      echo "bench_gpu.sh: bench failed for $name $preset:" >&2
      cat "$tmp/err.txt" >&2
      exit 3
    fi
    json=$(<"$tmp/out.json")
    if [[ -z $renderer ]]; then
      renderer=$(field "$json" /machine/gl_renderer)
      vendor=$(field "$json" /machine/gl_vendor)
      version=$(field "$json" /machine/gl_version)
      backend=$(field "$json" /machine/backend)
      if [[ $renderer == *llvmpipe* || $renderer == *softpipe* || $backend != egl-device ]]; then
        echo "bench_gpu.sh: EGL gave '$renderer' ($backend), not a GPU" >&2
        [[ ${ALLOW_SOFTWARE:-0} == 1 ]] || exit 3
      fi
    fi
    ms=$(field "$json" /frame_ms/gpu/median)
    [[ $(field "$json" /frame_ms/gpu_timer) == true ]] || ms=$(field "$json" /frame_ms/wall/median)
    gpu[$name.$preset]=$ms
    rows+=("$name|$preset|$ms|$(field "$json" /frame_ms/gpu/p95)|$(field "$json" /frame_ms/wall/median)|$(field "$json" /cost/primary_steps/mean)|$(field "$json" /cost/step_cap_fraction)|$(field "$json" /cost/sdf_evals/mean)|$(field "$json" /startup_ms/compile_link)")
  done
  if [[ -n ${SWEEP_DIR:-} ]]; then
    mkdir -p "$SWEEP_DIR"
    echo "bench_gpu.sh: sweep $name" >&2
    "$bin" sweep "$scene" --size "$size" --backend egl -q -o "$SWEEP_DIR" >"$SWEEP_DIR/$name.sweep.txt"
  fi
done

echo "GPU: \`$renderer\` ($vendor), $version, backend \`$backend\`; $size, spp 1, median of $frames frames after $warmup warm-up; $(date -u +%Y-%m-%d)."
echo
echo "Command: \`tools/gpu/bench_gpu.sh\` (each row: \`marchstudio bench scenes/SCENE.toml --preset PRESET --size $size --frames $frames --warmup $warmup --backend egl --json\`)"
echo
echo "| scene | preset | GPU ms median | p95 | wall ms median | speed-up vs textbook | primary steps / px | step-cap pixels | map() calls / px | compile+link ms |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for row in "${rows[@]}"; do
  IFS='|' read -r name preset ms p95 wall steps cap evals compile <<<"$row"
  speedup=$(awk -v a="${gpu[$name.textbook]}" -v b="$ms" 'BEGIN { if (b > 0) printf "%.2fx", a / b; else print "-" }')
  echo "| $name | $preset | $(fmt "$ms" %.3f) | $(fmt "$p95" %.3f) | $(fmt "$wall" %.3f) | $speedup | $(fmt "$steps" %.2f) | $(awk -v x="$cap" 'BEGIN { printf "%.3f%%", 100 * x }') | $(fmt "$evals" %.1f) | $(fmt "$compile" %.0f) |"
done
