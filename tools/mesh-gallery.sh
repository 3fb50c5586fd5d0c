#!/usr/bin/env bash
# Every gallery scene meshed at one resolution (default 512), each in a
# time box: seconds, peak memory, triangles, the check and the accuracy,
# into docs/mesh.md between <!-- mesh-gallery:begin/end -->.
#
#   tools/mesh-gallery.sh
#   RESOLUTION=256 TIMEBOX=120 tools/mesh-gallery.sh
#
# Resumable like tools/mesh-bench.sh: each scene's record is one JSON line
# in RESULTS (default build/mesh-gallery.jsonl); a scene already there at
# this resolution is skipped (delete its line to rerun it).
set -uo pipefail
cd "$(dirname "$0")/.."
MS=${MARCHSTUDIO:-build/marchstudio}
RESOLUTION=${RESOLUTION:-512}
TIMEBOX=${TIMEBOX:-300}
RESULTS=${RESULTS:-build/mesh-gallery.jsonl}
DOC=${DOC:-docs/mesh.md}
PY=/usr/bin/python3
mkdir -p "$(dirname "$RESULTS")"
touch "$RESULTS"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scenes=(scenes/*.toml)
i=0
for scene in "${scenes[@]}"; do
  i=$((i + 1))
  name=$(basename "$scene" .toml)
  if grep -q "\"scene\": \"$name\", \"resolution\": $RESOLUTION," "$RESULTS"; then
    echo "mesh-gallery: $i of ${#scenes[@]}: $name: already in $RESULTS" >&2
    continue
  fi
  echo "mesh-gallery: $i of ${#scenes[@]}: $name at $RESOLUTION" >&2
  t0=$(date +%s.%N)
  # Cold: an empty cache directory, so a graph's pruning pass runs.
  rm -rf "$tmp/cache"
  XDG_CACHE_HOME="$tmp/cache" /usr/bin/time -f %M -o "$tmp/mem" timeout --kill-after=10 "$TIMEBOX" \
    "$MS" mesh "$scene" -o "$tmp/x.ply" --resolution "$RESOLUTION" --json >"$tmp/out" 2>"$tmp/err"
  rc=$?
  t1=$(date +%s.%N)
  $PY - "$name" "$RESOLUTION" "$rc" "$t0" "$t1" "$TIMEBOX" "$tmp" >>"$RESULTS" <<'PYEOF'
import json, sys
name, res, rc, t0, t1, box, tmp = sys.argv[1:]
rec = {"scene": name, "resolution": int(res), "wall_s": round(float(t1) - float(t0), 2)}
mem = [l for l in open(tmp + "/mem").read().split() if l.isdigit()]
rec["peak_mb"] = round(int(mem[-1]) / 1024) if mem else None
if int(rc) in (124, 137):
    rec["status"] = "timeout"
elif int(rc) != 0:
    err = [l for l in open(tmp + "/err").read().splitlines() if l.strip()]
    rec.update(status="error", error=(err[-1] if err else "exit " + rc)[:200])
else:
    rec.update(status="ok", result=json.loads(open(tmp + "/out").read()))
print(json.dumps(rec))
PYEOF
  tail -n 1 "$RESULTS" | cut -c 1-160 >&2
  rm -f "$tmp/x.ply"
done
renderer=$("$MS" render scenes/seed.toml -o "$tmp/probe.png" --size 32x18 -v 2>&1 |
  sed -n 's/.*GL_RENDERER \(.*\), GL_VERSION.*/\1/p' | head -n 1)
machine="$(nproc) cores, $(uname -m), GL renderer ${renderer:-unknown}, $(date +%Y-%m-%d)"
$PY - "$RESULTS" "$DOC" "$machine" "$RESOLUTION" "$TIMEBOX" <<'PYEOF'
import json, sys
sys.path.insert(0, "tools")
from doc_markers import put
results, doc, machine, res, box = sys.argv[1:]
rows = {}
for line in open(results):
    r = json.loads(line)
    if r["resolution"] == int(res):
        rows[r["scene"]] = r
lines = ["", f"Every scene of scenes/ at `--resolution {res}`, measured on {machine} by tools/mesh-gallery.sh "
         "(wall seconds of the whole process, peak RSS; errors in voxels):", "",
         "| scene | seconds | peak MB | triangles | setup s | sampling s | meshing s | check s | max vertex error | Hausdorff | check |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
for name in sorted(rows):
    r = rows[name]
    if r["status"] != "ok":
        what = f"> {box} s" if r["status"] == "timeout" else "error: " + r.get("error", "")
        lines.append(f"| {name} | {what} | | | | | | | | | |")
        continue
    o, st = r["result"], r["result"]["stages"]
    lines.append(f"| {name} | {r['wall_s']:.1f} | {r['peak_mb']} | {o['triangles']:,} | {st['setup_s']:.1f} "
                 f"| {st['sample_s'] - st['setup_s']:.1f} | {st['mesh_s']:.1f} | {st['check_s']:.1f} "
                 f"| {o['max_vertex_error_voxels']:.3f} | {o['hausdorff_voxels']:.2f} "
                 f"| {'watertight' if o['manifold'] else o['check']['summary']} |")
put(doc, "mesh-gallery", lines + [""])
PYEOF
