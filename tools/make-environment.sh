#!/usr/bin/env bash
# Regenerates the environment map we ship and its pictures in the docs:
#   scenes/env/sky.exr       rendered from scenes/env/sky_gen.glsl (our own
#                            sky: a gradient, a ground and a small sun), 256x128
#   docs/images/environment/ envlight.png (the demo scene), gradient.png (the
#                            same scene with the two-colour sky, to compare)
# Usage: tools/make-environment.sh [path/to/marchstudio]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${1:-$ROOT/build/marchstudio}"
"$BIN" render "$ROOT/scenes/env/sky_gen.glsl" --size 256x128 -o "$ROOT/scenes/env/sky.exr" >/dev/null
mkdir -p "$ROOT/docs/images/environment"
"$BIN" render "$ROOT/scenes/envlight.toml" --size 640x360 --spp 4 -o "$ROOT/docs/images/environment/envlight.png" >/dev/null
"$BIN" render "$ROOT/scenes/seed.toml" --size 640x360 --spp 4 -o "$ROOT/docs/images/environment/gradient.png" >/dev/null
echo "wrote scenes/env/sky.exr and docs/images/environment/{envlight,gradient}.png"
