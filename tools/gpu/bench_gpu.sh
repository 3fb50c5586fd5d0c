#!/usr/bin/env bash
# Fragment against compute: `marchstudio bench --json` with
# `--dispatch fragment` and `--dispatch compute` side by side, for the
# textbook baseline and the fast / balanced / reference presets, every
# shipped scene, at 1280x720, 1920x1080 and 3840x2160, through EGL's device
# platform (the NVIDIA driver). One markdown table on stdout, a row per
# scene, preset and size: each dispatch's GPU-timer median and p95 and its
# wall median, and compute's speed-up, each row printed as it finishes (a
# run cut short keeps its rows). Progress and warnings go to stderr, so
# `tools/gpu/bench_gpu.sh > gpu.md` keeps only the table.
#
# Usage: tools/gpu/bench_gpu.sh [path/to/marchstudio]
#   The binary defaults to $MARCHSTUDIO, else build/marchstudio, else any
#   build*/marchstudio in the repository (a carried build).
# Environment:
#   FRAMES (default 60) and WARMUP (default 10): bench's --frames / --warmup
#   SIZES (default "1280x720 1920x1080 3840x2160"); SIZE=WxH, the old
#     one-size form, still works when SIZES is unset
#   SCENES (default: every scenes/*.toml), e.g. SCENES="seed stilllife"
#   PRESETS (default "textbook fast balanced reference")
#   DISPATCHES (default "fragment compute"); the speed-up column needs both
#   ALLOW_SOFTWARE=1: run even when EGL gives a software renderer (llvmpipe)
#   SWEEP_DIR=DIR: also run `marchstudio sweep` (quick grid, first size) per
#     scene and leave its CSV, JSON and plot in DIR
# A GPU-timer figure under 1 us a frame is printed as "-": llvmpipe answers
# GL_TIME_ELAPSED with ~0 around a compute dispatch, so compare wall there.
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
read -r -a sizes <<<"${SIZES:-${SIZE:-1280x720 1920x1080 3840x2160}}"
read -r -a presets <<<"${PRESETS:-textbook fast balanced reference}"
read -r -a dispatches <<<"${DISPATCHES:-fragment compute}"

# The GPU's EGL vendor and libraries (launch.sh): undo what the llvmpipe
# scripts pin, unless device_run.sh has already set this machine up.
# shellcheck source=launch.sh
source "$root/tools/gpu/launch.sh"
[[ ${MARCH_GPU_ENV:-} == 1 ]] || gpu_environment "$(cd "$(dirname "$bin")" && pwd)"

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

# shellcheck source=common.sh
source "$root/tools/gpu/common.sh"
fmt() { awk -v x="$1" 'BEGIN { printf "%.3f", x }'; }
timer() { awk -v x="$1" 'BEGIN { if (x < 0.001) print "-"; else printf "%.3f", x }'; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A fig
start=$(date +%s)

# The GL strings first, from a tiny run, so a software renderer stops the
# script before any row and the table's heading can name the GL.
if ! "$bin" bench "$root/scenes/${names[0]}.toml" --size 8x8 --frames 1 --warmup 0 --backend egl --json \
    >"$tmp/out.json" 2>"$tmp/err.txt"; then
  echo "bench_gpu.sh: the probe run failed:" >&2
  cat "$tmp/err.txt" >&2
  exit 3
fi
{ read -r renderer; read -r vendor; read -r version; read -r backend; } < <(fields "$tmp/out.json" \
  /machine/gl_renderer /machine/gl_vendor /machine/gl_version /machine/backend)
if why=$(not_a_gpu "$tmp/out.json"); then
  echo "bench_gpu.sh: $why" >&2
  [[ ${ALLOW_SOFTWARE:-0} == 1 ]] || exit 3
fi

# The heading, then each row as soon as its dispatches are measured: a run
# cut short (tools/gpu/device_run.sh's time box) keeps the rows it finished.
echo "GL: \`$renderer\` ($vendor), $version, backend \`$backend\`; spp 1, median and p95 (nearest rank) of $frames frames after $warmup warm-up; $(date -u +%Y-%m-%d)."
echo
echo "Command: \`FRAMES=$frames WARMUP=$warmup SIZES=\"${sizes[*]}\" PRESETS=\"${presets[*]}\" tools/gpu/bench_gpu.sh\` (each cell: \`marchstudio bench scenes/SCENE.toml --preset PRESET --size WxH --frames $frames --warmup $warmup --dispatch D --backend egl --json\`)"
echo
head="| scene | preset | size |" rule="|---|---|---|"
for d in "${dispatches[@]}"; do
  head+=" $d GPU ms median | p95 | wall ms median | p95 |"; rule+="---|---|---|---|"
done
both=0
if [[ " ${dispatches[*]} " == *" fragment "* && " ${dispatches[*]} " == *" compute "* ]]; then
  both=1; head+=" compute speed-up (GPU; wall) |"; rule+="---|"
fi
echo "$head primary steps / px | map() calls / px |"
echo "$rule---|---|"

# row SIZE NAME PRESET: the table row of measured figures.
row() {
  local size=$1 name=$2 preset=$3 d line f fr co
  line="| $name | $preset | $size |"
  for d in "${dispatches[@]}"; do
    f=(${fig[$size.$name.$preset.$d]})
    line+=" $(timer "${f[0]}") | $(timer "${f[1]}") | $(fmt "${f[2]}") | $(fmt "${f[3]}") |"
  done
  if (( both )); then
    fr=(${fig[$size.$name.$preset.fragment]}) co=(${fig[$size.$name.$preset.compute]})
    line+=" $(awk -v a="${fr[0]}" -v b="${co[0]}" -v c="${fr[2]}" -v e="${co[2]}" 'BEGIN {
      g = (a >= 0.001 && b >= 0.001) ? sprintf("%.2fx", a / b) : "-"
      printf "%s; %.2fx", g, c / e }') |"
  fi
  f=(${fig[$size.$name.$preset.${dispatches[0]}]})
  echo "$line $(awk -v x="${f[4]}" 'BEGIN { printf "%.2f", x }') | $(awk -v x="${f[5]}" 'BEGIN { printf "%.1f", x }') |"
}

for size in "${sizes[@]}"; do
  for name in "${names[@]}"; do
    scene=$root/scenes/$name.toml
    for preset in "${presets[@]}"; do
      for d in "${dispatches[@]}"; do
        echo "bench_gpu.sh: $size $name $preset $d ($(( $(date +%s) - start )) s)" >&2
        if ! "$bin" bench "$scene" --preset "$preset" --size "$size" --frames "$frames" --warmup "$warmup" \
            --dispatch "$d" --backend egl --json >"$tmp/out.json" 2>"$tmp/err.txt"; then
          echo "bench_gpu.sh: bench failed for $size $name $preset $d:" >&2
          cat "$tmp/err.txt" >&2
          exit 3
        fi
        # gpu median, gpu p95, wall median, wall p95, steps, map() calls
        fig[$size.$name.$preset.$d]=$(fields "$tmp/out.json" /frame_ms/gpu/median /frame_ms/gpu/p95 \
          /frame_ms/wall/median /frame_ms/wall/p95 /cost/primary_steps/mean /cost/sdf_evals/mean | paste -sd' ')
      done
      # The dispatches trace the same pixels; differing counts mean a bug.
      first=(${fig[$size.$name.$preset.${dispatches[0]}]})
      for d in "${dispatches[@]}"; do
        f=(${fig[$size.$name.$preset.$d]})
        [[ ${f[4]} == "${first[4]}" ]] || echo "bench_gpu.sh: $name $preset $size: $d steps ${f[4]} != ${first[4]}" >&2
      done
      row "$size" "$name" "$preset"
    done
  done
  if [[ -n ${SWEEP_DIR:-} && $size == "${sizes[0]}" ]]; then
    mkdir -p "$SWEEP_DIR"
    for name in "${names[@]}"; do
      echo "bench_gpu.sh: sweep $name" >&2
      "$bin" sweep "$root/scenes/$name.toml" --size "$size" --backend egl -q -o "$SWEEP_DIR" >"$SWEEP_DIR/$name.sweep.txt"
    done
  fi
done
echo "bench_gpu.sh: done in $(( $(date +%s) - start )) s" >&2
