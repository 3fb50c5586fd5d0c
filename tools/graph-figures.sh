#!/usr/bin/env bash
# The scene-graph table of docs/scene-graph.md: primitive evaluations per
# pixel, compile time and frame time against the number of primitives,
# pruned against --no-prune, and the pruning pass's time. compile_ms is
# bench's compile_link (compile, link and the first 1x1 frame that makes
# llvmpipe generate code) less the pruning pass it includes.
#
#   tools/graph-figures.sh [OUT_DIR] [COUNTS...]     # default: out/graph-figures 100 1000 3000 10000 30000
#
# Each count is a particle field (tools/make-graph-scenes.py) benched at
# 64x36 with one timed frame, on llvmpipe; then the 1,000-sphere smooth
# molecule (scenes/molecule.toml) the same way, as "molecule". Rows already in OUT_DIR/rows.csv
# are kept, so a killed run resumes. --no-prune is benched up to 3,000
# primitives: past that one llvmpipe frame takes hours, and its interpreter
# passes llvmpipe's loop limit (docs/scene-graph.md); its primitive count
# is then N times the map() calls, which pruning leaves unchanged.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${MARCHSTUDIO:-$root/build/marchstudio}
out=${1:-$root/out/graph-figures}
shift || true
counts=("$@")
(( ${#counts[@]} )) || counts=(100 1000 3000 10000 30000)
mkdir -p "$out"
csv=$out/rows.csv
[[ -f $csv ]] || echo "primitives,mode,compile_ms,frame_ms,prune_ms,sdf_evals_mean,primitive_evals_mean,primitive_evals_p99" > "$csv"
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
start=$(date +%s)
for n in "${counts[@]}" molecule; do
  for mode in pruned whole; do
    grep -q "^$n,$mode," "$csv" && continue
    dir=$out/n$n
    mkdir -p "$dir"
    if [[ $n == molecule ]]; then
      cp "$root/scenes/molecule.toml" "$root/scenes/molecule.json" "$dir/"
      scene=$dir/molecule.toml
    else
      if [[ $mode == whole ]] && (( n > 3000 )); then continue; fi
      [[ -f $dir/particles.json ]] || /usr/bin/python3 "$root/tools/make-graph-scenes.py" "$dir" --molecule 0 --particles "$n"
      sed -e 's|graph = "molecule.json"|graph = "particles.json"|' "$root/scenes/molecule.toml" > "$dir/scene.toml"
      scene=$dir/scene.toml
    fi
    flags=(--size 64x36 --frames 1 --warmup 0 --json)
    [[ $mode == whole ]] && flags+=(--no-prune --graph-eval interpreter)
    printf '\r%-60s elapsed %ds' "n=$n $mode" $(( $(date +%s) - start )) >&2
    "$bin" bench "$scene" "${flags[@]}" > "$dir/$mode.json.tmp"
    mv "$dir/$mode.json.tmp" "$dir/$mode.json"
    /usr/bin/python3 - "$dir/$mode.json" "$n" "$mode" >> "$csv" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1]))
c, g = j["cost"], j.get("graph", {})
pe = c.get("primitive_evals", {"mean": 0, "p99": 0})
print(",".join(str(x) for x in [sys.argv[2], sys.argv[3], round(j["startup_ms"]["compile_link"] - g.get("prune_ms", 0), 1), round(j["frame_ms"]["wall"]["median"], 1),
                                round(g.get("prune_ms", 0), 1), round(c["sdf_evals"]["mean"], 2),
                                round(pe["mean"], 2), pe["p99"]]))
EOF
  done
done
echo >&2
cat "$csv"
