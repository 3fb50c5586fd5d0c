#!/usr/bin/env bash
# Measures specialized against generic scene shaders for docs/specialization.md:
# assembled source size, active source (after the preprocessor), SPIR-V words
# (glslangValidator, as emitted and with -Os), compile+link and frame time
# (marchstudio bench, cold shader cache) and steps per pixel. Prints one
# markdown table row per scene and shader.
#
#   tools/measure-specialization.sh BUILD_DIR [ROUNDS] [SCENE.toml...]
#
# Timing runs are interleaved (spec, generic, spec, ...) over ROUNDS rounds
# (default 3) so load on a shared machine hits both alike. Each run's figure
# is the median of its 5 frames; the table gives the best run (load only
# adds time), with the median over runs beside it. Needs python3 and
# glslang-tools.
set -euo pipefail
BUILD=${1:?usage: $0 BUILD_DIR [ROUNDS] [SCENE.toml...]}
ROUNDS=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN="$BUILD/marchstudio"
SCENES=("$@")
if [ ${#SCENES[@]} -eq 0 ]; then
  SCENES=("$ROOT"/scenes/*.toml "$ROOT"/tests/data/specialize/*.toml)
fi
command -v glslangValidator >/dev/null || { echo "glslangValidator not found (apt-get install glslang-tools)" >&2; exit 2; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

flag() { [ "$1" = generic ] && echo --no-specialize || true; }

for scene in "${SCENES[@]}"; do
  name=$(basename "$scene" .toml)
  for mode in folded generic; do
    f="$TMP/$name.$mode"
    "$BIN" render "$scene" --print-shader $(flag $mode) > "$f.frag"
    glslangValidator -E -S frag "$f.frag" 2>/dev/null | grep -v -e '^\s*$' -e '^#line' > "$f.active"
    glslangValidator -G --aml -S frag -o "$f.spv" "$f.frag" >/dev/null
    glslangValidator -G --aml -Os -S frag -o "$f.os.spv" "$f.frag" >/dev/null
    echo "$(wc -c < "$f.frag") $(wc -c < "$f.active") $(( $(stat -c %s "$f.spv") / 4 )) $(( $(stat -c %s "$f.os.spv") / 4 ))" > "$f.size"
  done
done

for round in $(seq "$ROUNDS"); do
  for scene in "${SCENES[@]}"; do
    name=$(basename "$scene" .toml)
    for mode in folded generic; do
      "$BIN" bench "$scene" --size 1280x720 --frames 5 --warmup 1 --json $(flag $mode) > "$TMP/$name.$mode.$round.json"
    done
  done
done

python3 - "$TMP" "$ROUNDS" "${SCENES[@]}" <<'EOF'
import json, os, statistics, sys
tmp, rounds, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
renderer = None
print("| scene | shader | source bytes | active bytes | SPIR-V words | SPIR-V words -Os | compile+link ms | frame ms | primary steps / pixel | map() calls / pixel |")
print("|---|---|---|---|---|---|---|---|---|---|")
for scene in scenes:
    name = os.path.basename(scene)[:-5]
    row = {}
    for mode in ("folded", "generic"):
        sizes = [int(x) for x in open(f"{tmp}/{name}.{mode}.size").read().split()]
        runs = [json.load(open(f"{tmp}/{name}.{mode}.{r}.json")) for r in range(1, rounds + 1)]
        renderer = runs[0]["machine"]["gl_renderer"]
        row[mode] = dict(
            sizes=sizes,
            compile=[j["startup_ms"]["compile_link"] for j in runs],
            frame=[j["frame_ms"]["gpu"]["median"] for j in runs],
            steps={j["cost"]["primary_steps"]["mean"] for j in runs},
            evals={j["cost"]["sdf_evals"]["mean"] for j in runs})
    for mode, label in (("folded", "specialized"), ("generic", "generic")):
        r = row[mode]
        g = row["generic"]
        def cell(v, base, fmt):
            text = fmt % v
            return text if mode == "generic" else "%s (%+.0f%%)" % (text, 100.0 * (v - base) / base)
        cells = [cell(r["sizes"][i], g["sizes"][i], "%d") for i in range(4)]
        # Load on a shared machine only ever adds time: the best run is the
        # figure, the median over runs shows how noisy it was.
        for key, fmt in (("compile", "%.0f"), ("frame", "%.1f")):
            best = cell(min(r[key]), min(g[key]), fmt)
            cells.append(best + ((" (median " + fmt + ")") % statistics.median(r[key]) if rounds > 1 else ""))
        cells += [" / ".join("%.2f" % s for s in sorted(r["steps"])), " / ".join("%.2f" % s for s in sorted(r["evals"]))]
        print(f"| {name} | {label} | " + " | ".join(cells) + " |")
print()
print(f"GL_RENDERER: {renderer}; {rounds} interleaved rounds; percentages: specialized against generic (best runs)")
EOF
