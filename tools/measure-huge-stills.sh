#!/usr/bin/env bash
# Measures huge stills (docs/usage.md#huge-stills) on the release binary and
# writes the table between the <!-- huge-stills:begin --> and
# <!-- huge-stills:end --> markers of docs/reliability.md: for each size and
# format the exit status, the wall time, the peak memory of the whole
# process (/usr/bin/time -v), the file's size, the tiles the render used
# (-v) and the fingerprint `marchstudio info` reads back. Each case runs in
# its own scratch directory (the files are deleted once measured: a
# 32768x32768 EXR is several GB). Minutes per case on 2 cores; not a ctest:
# tests/cli/test_huge_still.cpp asserts the behaviour at small sizes.
#
# Usage: tools/measure-huge-stills.sh [SIZE ...]   (default: 32768)
#        MARCHSTUDIO=path/to/marchstudio tools/measure-huge-stills.sh 16384
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=$(realpath "${MARCHSTUDIO:-$root/build/marchstudio}")
if [[ ! -x "$bin" ]]; then
  echo "measure-huge-stills.sh: no marchstudio binary at '$bin' (build it, or set MARCHSTUDIO)" >&2
  exit 2
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "measure-huge-stills.sh: needs GNU time (/usr/bin/time; Debian: apt-get install time)" >&2
  exit 2
fi
sizes=("$@")
(( ${#sizes[@]} )) || sizes=(32768)
export LIBGL_ALWAYS_SOFTWARE=1 MARCH_SHADER_DIR=$root/sdf_shaders
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rows=$tmp/rows.tsv
: > "$rows"

for side in "${sizes[@]}"; do
  for ext in png exr; do
    d=$tmp/$side-$ext
    mkdir -p "$d"
    rc=0
    ( cd "$d" && /usr/bin/time -v -o time.txt "$bin" render "$root/scenes/seed.toml" --size "${side}x${side}" \
        -v -o "out.$ext" > out.txt 2> err.txt ) || rc=$?
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s}' "$d/time.txt")
    rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$d/time.txt")
    bytes=$(stat -c %s "$d/out.$ext" 2> /dev/null || echo 0)
    tiles=$(grep -o 'tiles of [0-9]*x[0-9]*' "$d/err.txt" | head -n 1 | sed 's/tiles of //' || true)
    # The fingerprint as `info` reads it back, else why it could not.
    fp=$("$bin" info "$d/out.$ext" 2> "$d/info.txt" | awk '/fingerprint:/ {print $2}' || true)
    [[ -n $fp ]] || fp=$(head -n 1 "$d/info.txt" | sed "s|$d/||g" | cut -c1-200)
    line=$(grep -v -e '^marchstudio: backend' -e '^marchstudio: shader' -e '^marchstudio: context' "$d/err.txt" | head -n 1 | cut -c1-200 || true)
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "${side}x${side}" "$ext" "$rc" "$wall" "$rss" "$bytes" "${tiles:--}" "${fp:-${line:-none}}" >> "$rows"
    echo "measured: ${side}x${side} $ext (exit $rc, ${wall} s, ${rss} MB)" >&2
    rm -rf "$d"
  done
done

machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB"
renderer=$("$bin" bench "$root/scenes/seed.toml" --size 8x8 --frames 1 --json | /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["machine"]["gl_renderer"])')
/usr/bin/python3 - "$rows" "$root" "$machine" "$renderer" "$(date -u +%Y-%m-%d)" <<'PY'
import sys
rows, root, machine, renderer, date = sys.argv[1:6]
sys.path.insert(0, root + "/tools")
from doc_markers import put
out = ["Measured by `tools/measure-huge-stills.sh` on %s, `GL_RENDERER` = `%s`, %s; release build," % (machine, renderer, date),
       "`render scenes/seed.toml --size WxH` at the scene's 1 spp. Time and peak memory are the whole process's",
       "(`/usr/bin/time -v`: start-up, context, rendering, encoding and the verified write).",
       "",
       "| size | format | exit | wall s | peak MB | file MB | tiles (W x band rows) | fingerprint read back |",
       "|---|---|---|---|---|---|---|---|"]
for line in open(rows):
    size, ext, rc, wall, rss, nbytes, tiles, fp = line.rstrip("\n").split("\t")
    out.append("| %s | %s | %s | %.0f | %s | %.0f | %s | `%s` |" % (size, ext.upper(), rc, float(wall), rss,
               int(nbytes) / 1e6, tiles.replace("x", " x "), fp.replace("|", "\\|")))
put(root + "/docs/reliability.md", "huge-stills", out)
PY
echo "wrote the huge-stills table in docs/reliability.md" >&2
