#!/usr/bin/env bash
# One GPU session's measurements of the dispatches, most wanted first, each stage
# under its own time box, so a session cut short still brings back what
# came first. Every stage writes its own file into the output directory as
# it finishes (docs/gpu-bench.md#gpu-figures):
#   info.txt        the GPU (nvidia-smi), the date, the binary's GL strings
#   targets.md      the issue's targets: seed, stilllife and columns at
#                   1920x1080, balanced preset, fragment against compute
#   host_costs.md   submit against the GPU timer (tools/gpu/host_costs.sh)
#   auto.json       what `--dispatch auto` chose for seed at 1920x1080
#   full_WxH.md     the whole side-by-side table, one file per size
#   log.txt         every stage's progress and its time
#
# Usage: tools/gpu/device_run.sh [path/to/marchstudio-gpubench]
#   (default .gpu/marchstudio-gpubench, as tools/gpu/pack.sh packs it; the
#   packed folder goes first on the library path, and where the machine's
#   glibc is too old the binary starts through the packed one: launch.sh)
# Environment:
#   OUT: the output directory (default gpu-out); the device tool's $OUT works
#   BUDGET_S (default 480): seconds for all the stages; a stage gets what
#     is left, the full table last, size by size
#   FRAMES (60) and WARMUP (10) for every bench run
#   TARGET_SIZE (1920x1080), HOST_SIZES ("1280x720 TARGET_SIZE"),
#   FULL_SIZES ("1280x720 1920x1080 3840x2160"; set empty, no full table),
#   FULL_SCENES and FULL_PRESETS (bench_gpu.sh's defaults: every scene and
#     preset): a smaller run, e.g. the llvmpipe check in tests/CMakeLists.txt
#   ALLOW_SOFTWARE=1: run on llvmpipe (the check; tables then say llvmpipe)
#   MARCH_SHADER_DIR (default the checkout's sdf_shaders)
# Exit codes: 0 every stage ran; 2 no binary; 3 no GPU behind EGL (unless
# ALLOW_SOFTWARE=1); 4 a stage failed or ran out of time (the others ran);
# 5 the binary does not start on this machine (log.txt says why).
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${1:-$root/.gpu/marchstudio-gpubench}
out=${OUT:-gpu-out}
budget=${BUDGET_S:-480}
target_size=${TARGET_SIZE:-1920x1080}
read -r -a full_sizes <<<"${FULL_SIZES-1280x720 1920x1080 3840x2160}"
export FRAMES=${FRAMES:-60} WARMUP=${WARMUP:-10}
if [[ ! -x $bin ]]; then
  echo "device_run.sh: no binary at $bin (build the lean bench: docs/gpu-bench.md#gpu-figures)" >&2
  exit 2
fi
export MARCH_SHADER_DIR=${MARCH_SHADER_DIR:-$root/sdf_shaders}
mkdir -p "$out"
out=$(cd "$out" && pwd)
log=$out/log.txt
start=$(date +%s)
failed=0
left() { echo $(( budget - ($(date +%s) - start) )); }
say() { echo "device_run.sh: $* ($(( $(date +%s) - start )) s)" | tee -a "$log" >&2; }

# stage NAME FILE COMMAND...: COMMAND's stdout into FILE, within the time
# left; a failure or a timeout is logged and the next stage runs.
stage() {
  local name=$1 file=$2; shift 2
  local t; t=$(left)
  if (( t < 5 )); then
    say "$name: skipped, the budget is spent"
    failed=1
    return
  fi
  say "$name: start (up to $t s)"
  timeout "$t" "$@" >"$file.part" 2>>"$log"
  local rc=$?
  if (( rc == 0 )); then
    mv "$file.part" "$file"
    say "$name: done"
  else
    say "$name: failed (exit $rc$( (( rc == 124 )) && echo ", out of time")); partial output in $file.part"
    failed=1
  fi
  return $rc
}

{
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(uname -n) $(uname -r), $(nproc) CPUs, $(ldd --version 2>/dev/null | head -1)"
  command -v nvidia-smi >/dev/null 2>&1 &&
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader
} >"$out/info.txt" 2>&1

# The library path and EGL vendor for this machine's driver, and a binary
# that starts here: the packed one, or the same through the packed glibc.
# shellcheck source=launch.sh
source "$root/tools/gpu/launch.sh"
gpu_environment "$(cd "$(dirname "$bin")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! bin=$(gpu_launcher "$bin" "$work" 2>>"$log"); then
  say "the binary does not start here: $(tail -1 "$log")"
  exit 5
fi
{
  echo "launch: $( [[ $bin == "$work"/* ]] && echo "through the packed glibc" || echo "plain")"
  echo "LD_LIBRARY_PATH: $LD_LIBRARY_PATH"
  echo "EGL vendor: ${__EGL_VENDOR_LIBRARY_FILENAMES:-none named, glvnd searches its folders}"
} >>"$out/info.txt"

# The GL strings, and the refusal of a software renderer, from one tiny run.
"$bin" bench "$root/scenes/seed.toml" --size 8x8 --frames 1 --warmup 0 --backend egl --json \
  >"$out/probe.json" 2>>"$log" || { say "probe: bench failed"; gpu_diagnosis >>"$log"; exit 3; }
grep -E '"(backend|gl_renderer|gl_vendor|gl_version)"' "$out/probe.json" >>"$out/info.txt"
# shellcheck source=common.sh
source "$root/tools/gpu/common.sh"
if why=$(not_a_gpu "$out/probe.json") && [[ ${ALLOW_SOFTWARE:-0} != 1 ]]; then
  say "$why"
  exit 3
fi
export ALLOW_SOFTWARE=${ALLOW_SOFTWARE:-0}

gpu=$root/tools/gpu
stage targets "$out/targets.md" env SCENES="seed stilllife columns" SIZES="$target_size" PRESETS=balanced \
  "$gpu/bench_gpu.sh" "$bin"
stage host_costs "$out/host_costs.md" env BENCH_FLAGS="--backend egl" SIZES="${HOST_SIZES:-1280x720 $target_size}" \
  "$gpu/host_costs.sh" "$bin"
stage auto "$out/auto.json" "$bin" bench "$root/scenes/seed.toml" --size "$target_size" --dispatch auto \
  --frames "$FRAMES" --warmup "$WARMUP" --backend egl --json
for size in "${full_sizes[@]}"; do
  stage "full $size" "$out/full_$size.md" env SIZES="$size" ${FULL_SCENES:+SCENES="$FULL_SCENES"} \
    ${FULL_PRESETS:+PRESETS="$FULL_PRESETS"} "$gpu/bench_gpu.sh" "$bin"
done
say "all stages: $( (( failed )) && echo "some failed or ran out of time" || echo ok)"
(( failed )) && exit 4
exit 0
