#!/usr/bin/env bash
# Where `--graph-eval auto` should switch from inline GLSL to the
# interpreter (docs/scene-graph.md): compile time and frame time of both,
# for particle fields of a few sizes, benched at 64x36 with one timed frame.
#
#   tools/graph-crossover.sh [OUT_DIR] [COUNTS...]   # default: out/graph-crossover 16 32 64 128 256
#
# Rows already in OUT_DIR/rows.csv are kept, so a killed run resumes.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${MARCHSTUDIO:-$root/build/marchstudio}
out=${1:-$root/out/graph-crossover}
shift || true
counts=("$@")
(( ${#counts[@]} )) || counts=(16 32 64 128 256)
mkdir -p "$out"
csv=$out/rows.csv
[[ -f $csv ]] || echo "primitives,eval,compile_ms,frame_ms,primitive_evals_mean" > "$csv"
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
start=$(date +%s)
for n in "${counts[@]}"; do
  for eval in inline interpreter; do
    grep -q "^$n,$eval," "$csv" && continue
    dir=$out/n$n
    mkdir -p "$dir"
    [[ -f $dir/particles.json ]] || /usr/bin/python3 "$root/tools/make-graph-scenes.py" "$dir" --molecule 0 --particles "$n"
    sed -e 's|graph = "particles.json"|graph = "particles.json"|' "$root/scenes/particles.toml" > "$dir/scene.toml"
    printf '\r%-40s elapsed %ds' "n=$n $eval" $(( $(date +%s) - start )) >&2
    "$bin" bench "$dir/scene.toml" --size 64x36 --frames 3 --warmup 1 --json --graph-eval "$eval" > "$dir/$eval.json.tmp"
    mv "$dir/$eval.json.tmp" "$dir/$eval.json"
    /usr/bin/python3 - "$dir/$eval.json" "$n" "$eval" >> "$csv" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
g = j.get("graph", {})
print(",".join(str(x) for x in [sys.argv[2], sys.argv[3], round(j["startup_ms"]["compile_link"] - g.get("prune_ms", 0), 1),
                                round(j["frame_ms"]["wall"]["median"], 1), round(j["cost"]["primitive_evals"]["mean"], 1)]))
PY
  done
done
echo >&2
cat "$csv"
