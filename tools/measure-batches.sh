#!/bin/bash
# Batch throughput (docs/performance.md#batches): N stills at WxH of three
# scenes (seed, columns, chamfer; each scene at several times, so the
# shaders repeat), rendered as one `render --jobs` process and as N
# `render` processes, alternately, ROUNDS times each; prints the median
# wall time of each, the ratio, the stills per second, and how many
# programs the batch compiled (from -v). Checks that both ways wrote the
# same bytes. Run from the repository root:
#
#   tools/measure-batches.sh [BIN] [N] [SIZE] [ROUNDS]   # defaults: build/marchstudio 50 320x180 3
set -euo pipefail
bin=$(realpath "${1:-build/marchstudio}")
n=${2:-50}
size=${3:-320x180}
rounds=${4:-3}
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/batch" "$work/single"
scenes=(seed columns chamfer)
: > "$work/jobs.jsonl"
: > "$work/singles.sh"
for ((i = 0; i < n; i++)); do
  s=${scenes[i % 3]}
  t=$(awk -v i="$i" 'BEGIN { printf "%.2f", (i / 3) * 0.1 }')
  printf '{"scene": "%s/scenes/%s.toml", "output": "batch/%03d.png", "time": %s}\n' "$root" "$s" "$i" "$t" \
    >> "$work/jobs.jsonl"
  printf '"%s" render "%s/scenes/%s.toml" -o single/%03d.png --size %s --time %s >/dev/null\n' \
    "$bin" "$root" "$s" "$i" "$size" "$t" >> "$work/singles.sh"
done
cd "$work"
now() { date +%s.%N; }
batch_s=() single_s=()
for ((r = 0; r < rounds; r++)); do
  t0=$(now)
  "$bin" render --jobs jobs.jsonl --size "$size" > /dev/null
  t1=$(now)
  bash singles.sh
  t2=$(now)
  batch_s+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')")
  single_s+=("$(awk -v a="$t1" -v b="$t2" 'BEGIN { print b - a }')")
done
for ((i = 0; i < n; i++)); do
  f=$(printf '%03d.png' "$i")
  cmp -s "batch/$f" "single/$f" || { echo "batch/$f differs from single/$f" >&2; exit 1; }
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
mb=$(median "${batch_s[@]}")
ms=$(median "${single_s[@]}")
compiled=$("$bin" render --jobs jobs.jsonl --size "$size" -v 2>&1 >/dev/null | sed -n 's/^marchstudio: batch: .*, \([0-9]*\) programs compiled, \([0-9]*\) from the cache$/\1 compiled, \2 reused/p')
echo "machine: $(. /etc/os-release && echo "$PRETTY_NAME"), $(nproc) cores, $("$bin" render "$root/scenes/seed.toml" --size 8x8 -o probe.png -v 2>&1 | sed -n 's/.*GL_RENDERER \(.*\), GL_VERSION \(.*\)$/\1, \2/p'); $(date -u +%Y-%m-%d)"
echo "$n stills at $size (seed, columns, chamfer), median of $rounds rounds; the files are byte-identical"
echo
echo "| how | wall time | stills/s |"
echo "|---|---|---|"
awk -v n="$n" -v s="$ms" 'BEGIN { printf "| %d processes | %.2f s | %.1f |\n", n, s, n / s }'
awk -v n="$n" -v s="$mb" 'BEGIN { printf "| one batch (--jobs) | %.2f s | %.1f |\n", s, n / s }'
awk -v a="$ms" -v b="$mb" 'BEGIN { printf "\nthe batch is %.1fx as fast; " , a / b }'
echo "its programs: $compiled"
