#!/usr/bin/env bash
# The dense baseline (tools/mesh-baseline.py) against `marchstudio mesh`,
# side by side, into docs/mesh.md between <!-- mesh-speed:begin/end -->.
#
#   tools/mesh-bench.sh
#   RESOLUTIONS="128 256" SUBJECTS="seed part" TIMEBOX=120 tools/mesh-bench.sh
#
# Each run is timed by its own wall clock and its peak RSS by /usr/bin/time,
# inside a time box (TIMEBOX s, default 300). Results go one JSON line each
# to RESULTS (default build/mesh-bench.jsonl); a run already there is
# skipped (unless it failed), so an interrupted bench resumes; deleting
# lines reruns them.
# A run that fails or overruns is a row saying so, never the end of the bench.
set -uo pipefail
cd "$(dirname "$0")/.."

MS=${MARCHSTUDIO:-build/marchstudio}
RESOLUTIONS=${RESOLUTIONS:-"128 256 512 1024"}
SUBJECTS=${SUBJECTS:-"seed part molecule"}
TIMEBOX=${TIMEBOX:-300}
RESULTS=${RESULTS:-build/mesh-bench.jsonl}
DOC=${DOC:-docs/mesh.md}
PY=/usr/bin/python3

mkdir -p "$(dirname "$RESULTS")"
touch "$RESULTS"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

scene_of() { echo "scenes/$1.toml"; }

# True when RESULTS holds tool/subject/resolution, done or timed out; a
# failed run is tried again (marchstudio's side fails until `mesh` exists).
done_already() {
  $PY - "$RESULTS" "$1" "$2" "$3" <<'EOF'
import json, sys
f, tool, subject, res = sys.argv[1:]
for line in open(f):
    try:
        r = json.loads(line)
    except ValueError:
        continue
    if (r.get("tool"), r.get("subject"), str(r.get("resolution"))) == (tool, subject, res) \
            and r.get("status") in ("ok", "timeout"):
        sys.exit(0)
sys.exit(1)
EOF
}

# Runs one command in the time box and appends its record to RESULTS.
run_one() {
  local tool=$1 subject=$2 res=$3
  shift 3
  local t0 t1 rc
  t0=$(date +%s.%N)
  /usr/bin/time -f %M -o "$tmp/mem" timeout --kill-after=10 "$TIMEBOX" "$@" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  t1=$(date +%s.%N)
  $PY - "$tool" "$subject" "$res" "$rc" "$t0" "$t1" "$TIMEBOX" "$tmp" >>"$RESULTS" <<'EOF'
import json, sys
tool, subject, res, rc, t0, t1, box, tmp = sys.argv[1:]
rec = {"tool": tool, "subject": subject, "resolution": int(res), "wall_s": round(float(t1) - float(t0), 3)}
mem = [l for l in open(tmp + "/mem").read().split() if l.isdigit()]
if mem:
    rec["peak_mb"] = round(int(mem[-1]) / 1024, 1)
def parse(text):  # one JSON object, on one line or pretty-printed
    for t in [text] + text.splitlines()[::-1]:
        try:
            o = json.loads(t)
            if isinstance(o, dict):
                return o
        except ValueError:
            pass
out = parse(open(tmp + "/out").read())
err = [l for l in open(tmp + "/err").read().splitlines() if l.strip()]
if int(rc) in (124, 137):
    rec.update(status="timeout", timebox_s=int(box))
elif int(rc) != 0 or out is None:
    rec.update(status="error", exit=int(rc), error=(err[-1] if err else "no JSON on stdout")[:300])
else:
    rec.update(status="ok", result=out)
print(json.dumps(rec))
EOF
}

subjects=($SUBJECTS)
resolutions=($RESOLUTIONS)
n=$((${#subjects[@]} * ${#resolutions[@]} * 2))
i=0
start=$(date +%s)
for subject in "${subjects[@]}"; do
  for res in "${resolutions[@]}"; do
    for tool in baseline marchstudio; do
      i=$((i + 1))
      if done_already "$tool" "$subject" "$res"; then
        echo "mesh-bench: run $i of $n: $tool $subject $res: already in $RESULTS" >&2
        continue
      fi
      echo "mesh-bench: run $i of $n: $tool $subject $res ($(( $(date +%s) - start )) s elapsed)" >&2
      if [ "$tool" = baseline ]; then
        run_one "$tool" "$subject" "$res" $PY tools/mesh-baseline.py --subject "$subject" --resolution "$res"
      else
        # Cold: an empty cache directory, so a graph's pruning pass runs.
        rm -rf "$tmp/cache"
        XDG_CACHE_HOME="$tmp/cache" run_one "$tool" "$subject" "$res" "$MS" mesh "$(scene_of "$subject")" \
          -o "$tmp/x.ply" --resolution "$res" --json
      fi
      tail -n 1 "$RESULTS" | cut -c 1-200 >&2
      rm -f "$tmp/x.ply"
    done
  done
done

# The machine: cores, architecture and the GL renderer marchstudio draws with.
renderer=$("$MS" render "$(scene_of seed)" -o "$tmp/probe.png" --size 32x18 -v 2>&1 |
  sed -n 's/.*GL_RENDERER \(.*\), GL_VERSION.*/\1/p' | head -n 1)
machine="$(nproc) cores, $(uname -m), GL renderer ${renderer:-unknown (marchstudio did not run)}, $(date +%Y-%m-%d)"

$PY - "$RESULTS" "$DOC" "$machine" "$SUBJECTS" <<'EOF'
import json, os, sys
sys.path.insert(0, "tools")
from doc_markers import put
results, doc, machine, subjects = sys.argv[1:]
runs = {}
for line in open(results):
    try:
        r = json.loads(line)
    except ValueError:
        continue
    runs[(r["subject"], r["resolution"], r["tool"])] = r  # the latest wins

def cell(r):
    if r is None:
        return "not run"
    if r["status"] == "timeout":
        return f"> {r['timebox_s']} s"
    if r["status"] == "error":
        return "error"
    return f"{r['wall_s']:.2f} s / {r.get('peak_mb', 0):.0f} MB"

order = {s: i for i, s in enumerate(subjects.split())}
keys = sorted({(s, n) for s, n, _ in runs}, key=lambda k: (order.get(k[0], 99), k[0], k[1]))
lines = ["", f"Measured on {machine}: wall seconds of the whole process (start-up included) / peak RSS, "
         "by tools/mesh-bench.sh. Errors are in voxels, from marchstudio's own report.", "",
         "| subject | resolution | baseline (numpy + marching cubes) | marchstudio mesh | speed-up "
         "| triangles | max vertex error | Hausdorff | check |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
for s, n in keys:
    b, m = runs.get((s, n, "baseline")), runs.get((s, n, "marchstudio"))
    up = "—"
    if b and m and b["status"] == "ok" and m["status"] == "ok":
        up = f"{b['wall_s'] / m['wall_s']:.1f}x"
    elif b and m and b["status"] == "timeout" and m["status"] == "ok":
        up = f"> {b['timebox_s'] / m['wall_s']:.0f}x"
    acc = "| — | — | — | — |"
    if m and m["status"] == "ok":
        o = m["result"]
        acc = (f"| {o['triangles']:,} | {o['max_vertex_error_voxels']:.4f} | {o['hausdorff_voxels']:.3f} "
               f"| {'watertight' if o['manifold'] else o['check']['summary']} |")
    lines.append(f"| {s} | {n} | {cell(b)} | {cell(m)} | {up} {acc}")
errors = sorted({r["error"] for r in runs.values() if r["status"] == "error"})
lines += [""] + [f"Error: `{e}`" for e in errors[:5]] + ([""] if errors else [])
if not os.path.exists(doc):
    open(doc, "w").write("# Meshes\n\n<!-- mesh-speed:begin -->\n<!-- mesh-speed:end -->\n")
put(doc, "mesh-speed", lines)
print(f"mesh-bench: {len(keys)} rows into {doc}", file=sys.stderr)
EOF
