#!/usr/bin/env bash
# docs/mesh.md's pictures: each scene's render beside a flat-shaded picture
# of the mesh `marchstudio mesh` exports from it (tools/mesh-shot, from the
# scene's own camera), and a wireframe close-up of the CSG part's edges.
#
#   tools/mesh-figures.sh            # needs build/marchstudio and build/mesh-shot
set -euo pipefail
cd "$(dirname "$0")/.."
MS=${MARCHSTUDIO:-build/marchstudio}
SHOT=${MESH_SHOT:-build/mesh-shot}
OUT=docs/images/mesh
SIZE=480x270
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in seed part molecule; do
  echo "mesh-figures: $s" >&2
  "$MS" render "scenes/$s.toml" --size "$SIZE" -o "$OUT/$s-render.png"
  "$MS" mesh "scenes/$s.toml" --resolution 128 -o "$tmp/$s.ply"
  "$SHOT" "$tmp/$s.ply" --scene "scenes/$s.toml" --size "$SIZE" -o "$OUT/$s-mesh.png"
done
# Coarse on purpose: at 48 cells the triangles are large enough to see
# that the box's edges and the bores' rims are kept sharp.
"$MS" mesh scenes/part.toml --resolution 48 -o "$tmp/part48.ply"
"$SHOT" "$tmp/part48.ply" --scene scenes/part.toml --size "$SIZE" --wire -o "$OUT/part-wire.png"
