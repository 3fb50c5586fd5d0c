#!/usr/bin/env bash
# An animated 10,000-primitive graph (docs/scene-graph.md#animation): one
# sphere of scenes/particles.json named and moved by an [[animation]]
# track. A still with -v gives the whole pruning pass's time; the
# sequence with -v prints per frame the programs compiled, the pruning
# time and the cells pruned again (shader/graph_repose.h). What it shows:
# after the first frame a pose compiles nothing, and prunes only near
# what moved.
#
#   tools/measure-graph-pose.sh [OUT_DIR] [FRAMES]   # default: out/graph-pose 4
#
# Writes its table into docs/scene-graph.md (the graph-pose markers).
#
# About a minute on llvmpipe (2 cores): two whole pruning passes of ~13 s.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${MARCHSTUDIO:-$root/build/marchstudio}
out=${1:-$root/out/graph-pose}
frames=${2:-4}
mkdir -p "$out"
/usr/bin/python3 - "$root/scenes/particles.json" "$out/particles.json" <<'PY'
import json, sys
g = json.load(open(sys.argv[1]))
g["root"]["children"][0]["name"] = "mover"  # the first sphere, at a translate of its own
json.dump(g, open(sys.argv[2], "w"))
PY
sed -e 's/^graph = .*/graph = "particles.json"/' "$root/scenes/particles.toml" > "$out/particles.toml"
cat >> "$out/particles.toml" <<'TOML'

[[animation]]
target = "graph.mover.translate"
keys   = [[0.0, 2.7362, 2.3722, -2.6607], [1.0, 2.4, 2.2, -2.4]]
TOML
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
# A cache of its own, empty: every pass is timed, none read back.
export XDG_CACHE_HOME="$out/cache" MARCH_PRUNE_CACHE_MS=1000000000
rm -rf "$out/cache"
echo "machine: $(nproc) cores, $(uname -m); $(date -u +%F)"
echo "whole pass (a still at t = 0):"
"$bin" render "$out/particles.toml" --time 0 --size 64x36 -o "$out/still.png" -v 2>&1 |
  grep -oE "GL_RENDERER [^,]*|grid .*" | tee "$out/still.log"
echo "the sequence:"
"$bin" render "$out/particles.toml" --frames "0..$((frames - 1))" --fps "$((frames - 1 > 0 ? frames - 1 : 1))" \
  --size 64x36 --force -o "$out/pose_%d.png" -v 2>&1 | grep -E "graph posed" | tee "$out/frames.log"
# The table of docs/scene-graph.md#animation, between its graph-pose markers.
/usr/bin/python3 - "$root" "$out" <<'PY'
import datetime, os, re, sys
root, out = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(root, 'tools'))
from doc_markers import put
whole = re.search(r'pruning ([0-9.]+) ms', open(os.path.join(out, 'still.log')).read())
cells = re.search(r'\(\d+ of (\d+) cells\)', open(os.path.join(out, 'frames.log')).read())
rows = ['| 10,000 spheres, one moving (64x36, %s) | cells pruned | pruning |' % datetime.date.today(), '|---|---|---|',
        '| whole pass (a still) | {:,} | {:,.0f} ms |'.format(int(cells.group(1)), float(whole.group(1)))]
for m in re.finditer(r'frame (\d+): .*pruning ([0-9.]+) ms \((\d+) of', open(os.path.join(out, 'frames.log')).read()):
    what = 'frame 0 (the pose it was prepared at)' if m.group(1) == '0' else 'frame ' + m.group(1)
    rows.append('| {} | {:,} | {:,.0f} ms |'.format(what, int(m.group(3)), float(m.group(2))))
put(os.path.join(root, 'docs', 'scene-graph.md'), 'graph-pose', rows)
PY
