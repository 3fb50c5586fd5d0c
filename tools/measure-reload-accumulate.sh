#!/bin/bash
# Seconds from a reload's adoption to the converged image in the viewer,
# for an accumulating scene (spp 4, 160x90) after a save of a map whose
# dead branch makes llvmpipe's JIT take seconds (docs/viewer.md, "How a
# reload compiles"). Short: the worker warmed the blended state too; long:
# its JIT ran on the UI thread at the second frame. Needs xvfb-run.
#   tools/measure-reload-accumulate.sh [build/marchstudio]
set -eu
BIN=$(realpath "${1:-build/marchstudio}")
D=$(mktemp -d); trap 'pkill -f "$D/acc.toml" || true; [ -n "${KEEP:-}" ] || rm -rf "$D"' EXIT
export MESA_SHADER_CACHE_DIR=$D/cache
cat > "$D/acc.toml" <<'TOML'
[scene]
map = "map.glsl"
[camera]
position = [0.0, 1.6, -5.0]
target = [0.0, 0.8, 0.0]
[render]
spp = 4
[[lights]]
position = [4.0, 5.0, -1.5]
[[materials]]
name = "floor"
color = [0.6, 0.6, 0.6]
[[materials]]
name = "ball"
color = [0.85, 0.10, 0.06]
TOML
map() {  # $1: extra GLSL before map(), $2: a statement inside it
  printf '%s\nvec2 map(vec3 p) {\n  vec2 ball = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), 1.0), 1.0);\n%s\n  return opUnion(vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), 0.0), ball);\n}\n' "$1" "$2"
}
map "" "" > "$D/map.glsl"
heavy="float heavy(vec3 p) {\n  float a = $RANDOM.0;\n"
for i in $(seq 60); do heavy+="  p = sin(p * 1.$i + p.yzx); a += p.x * p.z;\n"; done
heavy+="  return a;\n}"
xvfb-run -a -s "-screen 0 640x480x24" "$BIN" view "$D/acc.toml" --size 160x90 --paused --no-panel \
  --log "$D/log.txt" --exit-after 300 >/dev/null 2>"$D/err.txt" &
viewer=$!
until grep -q "^converged" "$D/log.txt" 2>/dev/null; do
  kill -0 $viewer 2>/dev/null || { cat "$D/err.txt" >&2; exit 1; }; sleep 0.2
done
(tail -n0 -F "$D/log.txt" 2>/dev/null | while read -r l; do echo "$(date +%s.%N) $l"; done > "$D/ts.txt") &
sleep 0.5
map "$(printf "$heavy")" "  if (p.y > 1e6) ball.x = heavy(p);" > "$D/.map.swp"; mv "$D/.map.swp" "$D/map.glsl"
until grep -q " converged" "$D/ts.txt" 2>/dev/null; do sleep 0.2; done
awk '/ reload ok 1 /{a=$1; for (i=2;i<=NF;i++) if ($i ~ /^warm_ms=/) w=$i} / converged/{c=$1}
     END {printf "adopted to converged: %.2f s (worker %s)\n", c-a, w}' "$D/ts.txt"
