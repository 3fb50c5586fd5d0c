#!/usr/bin/env bash
# Measures the input and output limits on the release binary and writes the
# table between the <!-- limits:begin --> and <!-- limits:end --> markers of
# docs/reliability.md: for each attack the exit status, the wall time and
# the peak memory (/usr/bin/time -v, the whole process), and the first line
# it printed. Every case runs in its own scratch directory with an empty
# MESA_SHADER_CACHE_DIR, so no outcome comes from an earlier compile. About
# a minute on 2 cores (the 20,000-term sum is most of it). Not a ctest:
# tests/cli/test_attacks_*.cpp assert the outcomes; this only measures.
#
# Usage: tools/measure-limits.sh [path/to/marchstudio]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=$(realpath "${1:-${MARCHSTUDIO:-$root/build/marchstudio}}")
if [[ ! -x "$bin" ]]; then
  echo "measure-limits.sh: no marchstudio binary at '$bin' (build it, or pass its path)" >&2
  exit 2
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "measure-limits.sh: needs GNU time (/usr/bin/time; Debian: apt-get install time)" >&2
  exit 2
fi
export LIBGL_ALWAYS_SOFTWARE=1 MARCH_SHADER_DIR=$root/sdf_shaders
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rows=$tmp/rows.tsv
: > "$rows"
main='void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }'

# case NAME SETUP COMMAND...: SETUP (shell text) runs in a fresh directory,
# then COMMAND under /usr/bin/time -v; one row: name, exit, s, MB, line.
case_() {
  local name=$1 setup=$2; shift 2
  local d=$tmp/case$(wc -l < "$rows")
  mkdir -p "$d" && cd "$d"
  eval "$setup"
  local rc=0 before
  before=$(ls -A "$d")
  MESA_SHADER_CACHE_DIR=$d/mesa-cache timeout 300 /usr/bin/time -v -o "$d/time.txt" "$@" > "$d/out.txt" 2> "$d/err.txt" || rc=$?
  local wall rss line
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$d/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$d/time.txt")
  line=$(grep -v '^\s*Command exited with non-zero status' "$d/err.txt" | head -n 1 | sed "s|$d/||g" | cut -c1-300 || true)
  [[ -n $line ]] || line=$(head -n 1 "$d/out.txt" | cut -c1-300 || true)
  # What the command left in its directory (temporaries included).
  local made
  made=$(comm -13 <(echo "$before" | sort) <(ls -A "$d" | grep -v -x -e mesa-cache -e time.txt -e out.txt -e err.txt | sort) | tr '\n' ' ')
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$rc" "$wall" "$rss" "${made:-nothing}" "$line" >> "$rows"
  echo "measured: $name (exit $rc, ${wall} s)" >&2
  cd "$tmp"
}

sum() {  # a Shadertoy shader whose one statement sums $1 terms
  awk -v n="$1" 'BEGIN { printf "void mainImage(out vec4 c, in vec2 f) {\n  float k = f.x"; for (i = 1; i < n; ++i) printf " + f.x"; printf ";\n  c = vec4(fract(k / 7.0));\n}\n" }'
}
bomb() {
  echo '#define A0 f.x'
  for i in $(seq 1 29); do echo "#define A$i A$((i - 1)), A$((i - 1))"; done
  echo 'void mainImage(out vec4 c, in vec2 f) { c = vec4(A29); }'
}
diamond() {  # f0 .. f40, each including the next twice: 2^40 expansions unguarded
  for i in $(seq 0 39); do printf '#include "f%d.glsl"\n#include "f%d.glsl"\n' $((i + 1)) $((i + 1)) > f$i.glsl; done
  echo 'float leaf() { return 1.0; }' > f40.glsl
  { echo '#include "f0.glsl"'; echo "$main"; } > main.glsl
}
guarded() {  # the same diamond, each file with an include guard
  for i in $(seq 0 39); do printf '#ifndef F%d\n#define F%d\n#include "f%d.glsl"\n#include "f%d.glsl"\n#endif\n' $i $i $((i + 1)) $((i + 1)) > f$i.glsl; done
  printf '#ifndef F40\n#define F40\nfloat leaf() { return 1.0; }\n#endif\n' > f40.glsl
  { echo '#include "f0.glsl"'; echo "$main"; } > main.glsl
}
chain() {  # $1 user files deep: the shader (level 1, the generated root includes it), c2 .. c$1
  for i in $(seq 2 "$1"); do
    if (( i < $1 )); then echo "#include \"c$((i + 1)).glsl\"" > c$i.glsl; else echo 'float deepest() { return 1.0; }' > c$i.glsl; fi
  done
  { echo '#include "c2.glsl"'; echo "$main"; } > main.glsl
}

buffered() {  # a Shadertoy project: Buffer A, which the Image pass shows
  cat <<'JSON'
{"Shader": {"info": {"name": "b"}, "renderpass": [
  {"name": "Buffer A", "type": "buffer", "code": "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }",
   "inputs": [], "outputs": [{"id": 257, "channel": 0}]},
  {"name": "Image", "type": "image", "code": "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }",
   "inputs": [{"id": 257, "ctype": "buffer", "channel": 0}], "outputs": []}]}}
JSON
}

# The deepest sum accepted: the longest within the depth limit (50,000 levels).
deepest=50000
while (( deepest > 49900 )); do
  sum $deepest > "$tmp/probe.glsl"
  if "$bin" render "$tmp/probe.glsl" --print-shader > /dev/null 2>&1; then break; fi
  deepest=$((deepest - 1))
done
rm -f "$tmp/probe.glsl"
case_ "a 20,000-term sum, 8x8 (crashed Mesa on the 8 MiB main stack)" 'sum 20000 > sum.glsl' "$bin" render sum.glsl --size 8x8 -o sum.png
case_ "the longest sum accepted: $deepest terms, 8x8" "sum $deepest > sum.glsl" "$bin" render sum.glsl --size 8x8 -o sum.png
case_ "a 60,000-term sum" 'sum 60000 > sum.glsl' "$bin" render sum.glsl -o sum.png
case_ "a macro bomb, #define A1 A0, A0 ... A29 (2^29 tokens)" 'bomb > bomb.glsl' "$bin" render bomb.glsl -o bomb.png
case_ "an include diamond of 41 files, unguarded" 'diamond' "$bin" render main.glsl -o out.png
case_ "the same diamond, every file guarded (#ifndef)" 'guarded' "$bin" render main.glsl --size 8x8 -o out.png
case_ "an include chain 200 user files deep (the shader is level 1)" 'chain 200' "$bin" render main.glsl --size 8x8 -o out.png
case_ "an include chain 201 user files deep" 'chain 201' "$bin" render main.glsl --size 8x8 -o out.png
case_ "#error after the same shader compiled (warm cache)" \
  'echo "$main" > m.glsl; MESA_SHADER_CACHE_DIR=$d/mesa-cache "$bin" render m.glsl --size 8x8 -o a.png > /dev/null; { echo "#error needs a newer marchstudio"; echo "$main"; } > m.glsl' \
  "$bin" render m.glsl --size 8x8 -o b.png
case_ "the seed as a PNG onto a full disk (ulimit -f 32: 32 KiB), 640x360" ':' \
  bash -c 'ulimit -f 32; exec "$0" render "$1" --size 640x360 -o out.png' "$bin" "$root/scenes/seed.toml"
case_ "the seed as a JPEG onto a full disk (ulimit -f 4: 4 KiB), 640x360" ':' \
  bash -c 'ulimit -f 4; exec "$0" render "$1" --size 640x360 -o out.jpg' "$bin" "$root/scenes/seed.toml"
case_ "compare with a FIFO as the reference" 'mkfifo fifo.png; "$bin" render "$root/scenes/seed.toml" --size 16x16 -o a.png > /dev/null' \
  "$bin" compare a.png fifo.png
case_ "compare with /dev/zero as the reference" '"$bin" render "$root/scenes/seed.toml" --size 16x16 -o a.png > /dev/null' \
  "$bin" compare a.png /dev/zero
case_ "--timeout 1e10 on a normal render (capped at a century)" ':' "$bin" render "$root/scenes/seed.toml" --size 64x36 --timeout 1e10 -o t.png
case_ "--size 8192x8192, no AOVs (the largest square within 4 GiB)" ':' "$bin" render "$root/scenes/seed.toml" --size 8192x8192 -o big.png
case_ "--size 8193x8193 (past the budget: drawn in tiles, streamed)" ':' "$bin" render "$root/scenes/seed.toml" --size 8193x8193 -o big.png
case_ "--size 8193x8193, a shader with a buffer (needs it whole-frame)" 'buffered > b.json' \
  "$bin" render b.json --size 8193x8193 -o big.png

machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB"
renderer=$("$bin" bench "$root/scenes/seed.toml" --size 8x8 --frames 1 --json | /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["machine"]["gl_renderer"])')
/usr/bin/python3 - "$rows" "$root/docs/reliability.md" "$machine" "$renderer" "$(date -u +%Y-%m-%d)" <<'PY'
import sys
rows, doc, machine, renderer, date = sys.argv[1:6]
out = ["<!-- limits:begin -->",
       "Measured by `tools/measure-limits.sh` on %s, `GL_RENDERER` = `%s`, %s; release build, each case" % (machine, renderer, date),
       "in a fresh directory with an empty `MESA_SHADER_CACHE_DIR`. Time and peak memory are the whole process's",
       "(`/usr/bin/time -v`: start-up and GL context included). *Left*: the files the command left in its directory,",
       "temporaries included.",
       "",
       "| attack | exit | wall s | peak MB | left | first line printed |",
       "|---|---|---|---|---|---|"]
for line in open(rows):
    name, rc, wall, rss, made, msg = line.rstrip("\n").split("\t")
    msg = "`%s`" % msg.replace("|", "\\|").replace("`", "'") if msg else ""
    out.append("| %s | %s | %.2f | %s | %s | %s |" % (name.replace("|", "\\|"), rc, float(wall), rss, made.strip(), msg))
out.append("<!-- limits:end -->")
text = open(doc).read()
b, e = text.index("<!-- limits:begin -->"), text.index("<!-- limits:end -->") + len("<!-- limits:end -->")
open(doc, "w").write(text[:b] + "\n".join(out) + text[e:])
PY
echo "wrote the limits table in docs/reliability.md" >&2
