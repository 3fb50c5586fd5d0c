#!/usr/bin/env bash
# Measures what a multi-pass Shadertoy frame costs beyond its passes' draws
# and writes the table between <!-- multipass-bench:begin --> and
# <!-- multipass-bench:end --> in docs/shadertoy.md: `marchstudio bench`
# times the whole frame (all passes, buffer swaps, mipmaps, the post pass,
# the read-back) and each pass alone (glFinish before and after it); the
# overhead is the frame's median over the sum of the passes' medians.
# The aim is at most 5% on llvmpipe.
#
# Usage: tools/multipass-bench.sh [path/to/marchstudio]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
if [[ ! -x "$bin" ]]; then
  echo "multipass-bench.sh: no marchstudio binary at '$bin' (build it, or pass its path)" >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shader="$root/docs/examples/shadertoy/feedback.json"
sizes="320x180 640x360 1280x720"
for size in $sizes; do
  "$bin" bench "$shader" --size "$size" --frames 30 --warmup 3 --json > "$tmp/$size.json"
  echo "measured $size" >&2
done
machine="$(nproc) cores, $(uname -m), $(. /etc/os-release && echo "$PRETTY_NAME")"
/usr/bin/python3 - "$tmp" "$root/docs/shadertoy.md" "$machine" "$(date -u +%Y-%m-%d)" $sizes <<'PY'
import json, os, sys
tmp, doc, machine, date = sys.argv[1:5]
sizes = sys.argv[5:]
rows, renderer, names = [], "", []
for size in sizes:
    j = json.load(open(os.path.join(tmp, size + ".json")))
    renderer = j["machine"]["gl_renderer"]
    frame = j["frame_ms"]["wall"]["median"]
    passes = [p["wall"]["median"] for p in j["pass_ms"]]
    names = [p["name"] for p in j["pass_ms"]]
    total = sum(passes)
    rows.append("| %s | %s | %.2f | %.2f | %+.1f%% |" % (
        size, " | ".join("%.2f" % m for m in passes), total, frame, 100.0 * (frame / total - 1.0)))
    print("%s: frame %.2f ms, passes %.2f ms" % (size, frame, total), file=sys.stderr)
table = ["<!-- multipass-bench:begin -->",
         "Measured by `tools/multipass-bench.sh` on %s, EGL surfaceless, `GL_RENDERER` = `%s`, %s:" % (
             machine, renderer, date),
         "`docs/examples/shadertoy/feedback.json`, wall-clock medians (ms) of 30 frames after 3 warm-ups.",
         "",
         "| size | " + " | ".join(names) + " | sum of the passes | whole frame | frame over the sum |",
         "|---|" + "---|" * (len(names) + 3)] + rows + ["<!-- multipass-bench:end -->"]
text = open(doc).read()
b = text.index("<!-- multipass-bench:begin -->")
e = text.index("<!-- multipass-bench:end -->") + len("<!-- multipass-bench:end -->")
open(doc, "w").write(text[:b] + "\n".join(table) + text[e:])
PY
echo "wrote the table in docs/shadertoy.md" >&2
