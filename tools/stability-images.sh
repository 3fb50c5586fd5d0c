#!/usr/bin/env bash
# Renders docs/images/stability/ (docs/stability.md): every case of
# scenes/hard/ with the default preset at its own size (160x90, the size the
# tests check), and the variants that show what a guard prevents. The one
# image it leaves alone is grazing-before.png: the tracer before the fix of
# commit 110bc58, which no flag brings back.
#
# Usage: tools/stability-images.sh [path/to/marchstudio]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
[[ -x $bin ]] || { echo "stability-images.sh: no marchstudio binary at '$bin'" >&2; exit 2; }
out=$root/docs/images/stability
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$root"/scenes/hard/* "$tmp"/

render() { "$bin" render "$tmp/$1.toml" -o "$out/$2.png" "${@:3}" >/dev/null; }
# A copy of case $1 edited by the sed script $2, rendered as $3.png.
variant() {
  sed -e "$2" "$tmp/$1.toml" >"$tmp/$3.toml"
  cmp -s "$tmp/$1.toml" "$tmp/$3.toml" && { echo "stability-images.sh: '$2' changed nothing in $1.toml" >&2; exit 1; }
  render "$3" "$3"
}

for c in grazing silhouette thin far offset inside on_surface twist bend displace squash acne normals degenerate mirrors; do
  render "$c" "$c"
done
# Case 3: a hit tolerance of 3 footprints closes the hairline gap
# (HardThin.AWideToleranceClosesTheGap).
variant thin 's/^\[render\]/[quality]\nhit_tolerance = 3.0\n\n[render]/' thin-wide
# Case 6: each deformed field with lipschitz = 1, overshooting.
for c in twist bend displace squash; do
  variant "$c" 's/^lipschitz = .*/lipschitz = 1.0/' "$c-lipschitz1"
done
echo "wrote $out"
