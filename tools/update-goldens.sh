#!/usr/bin/env bash
# Re-render every golden image, tests/golden/<scene>.png, for every
# scenes/<scene>.toml, and refresh the gallery copies in
# docs/images/gallery/. Then measure each backend against the new goldens,
# so the tolerances in tests/golden/suite.toml can be checked (and edited
# by hand). `marchstudio test tests/golden/suite.toml --update` would write
# only missing and failing goldens; this script re-renders them all.
#
# Explicit only: a person runs it, looks at docs/gallery.md, and commits the
# result. It refuses to run in CI, where it would turn every regression into
# a new "correct".
#
# Usage: tools/update-goldens.sh [path/to/marchstudio] [scene ...]
#   The binary defaults to $MARCHSTUDIO, else build/marchstudio. With scene
#   names (e.g. `menger city`) only those goldens are rendered, so adding a
#   scene does not touch the others' goldens.
set -euo pipefail

if [[ "${CI:-}" == "true" ]]; then
  echo "update-goldens.sh: refusing to run with CI=true: goldens are updated by a person, reviewed and committed" >&2
  exit 2
fi

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
shift $(( $# > 0 ? 1 : 0 ))
only=("$@")
if [[ ! -x "$bin" ]]; then
  echo "update-goldens.sh: no marchstudio binary at '$bin' (build it, or pass its path)" >&2
  exit 2
fi

# The goldens' definition: this size, this backend, every other setting the scene's.
size=160x90
backend=egl

# Goldens are llvmpipe references. On a machine with a GPU, glvnd would hand
# EGL to the GPU's driver: pin Mesa, and software rendering within Mesa.
mesa_vendor=/usr/share/glvnd/egl_vendor.d/50_mesa.json
if [[ -f $mesa_vendor ]]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$mesa_vendor; fi
export LIBGL_ALWAYS_SOFTWARE=1

golden_dir=$root/tests/golden
gallery_dir=$root/docs/images/gallery
mkdir -p "$golden_dir" "$gallery_dir"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

shopt -s nullglob
scenes=("$root"/scenes/*.toml)
if (( ${#scenes[@]} == 0 )); then
  echo "update-goldens.sh: no scenes in $root/scenes" >&2
  exit 2
fi
if (( ${#only[@]} > 0 )); then
  scenes=()
  for name in "${only[@]}"; do
    if [[ ! -f $root/scenes/$name.toml ]]; then
      echo "update-goldens.sh: no scenes/$name.toml" >&2
      exit 2
    fi
    scenes+=("$root/scenes/$name.toml")
  done
fi

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .toml)
  log=$("$bin" render "$scene" -o "$tmp/$name.png" --size "$size" --backend "$backend" -v 2>&1 >/dev/null)
  if [[ $log != *llvmpipe* ]]; then
    echo "update-goldens.sh: $name did not render on llvmpipe; refusing to write a golden:" >&2
    echo "$log" >&2
    exit 3
  fi
  cp "$tmp/$name.png" "$golden_dir/$name.png"
  cp "$tmp/$name.png" "$gallery_dir/$name.png"
  echo "golden: tests/golden/$name.png ($size, $backend, llvmpipe)"
done

# Goldens whose scene is gone would only confuse a reviewer.
for g in "$golden_dir"/*.png "$gallery_dir"/*.png; do
  name=$(basename "$g" .png)
  if [[ ! -f "$root/scenes/$name.toml" ]]; then
    rm -f "$g"
    echo "removed: ${g#"$root"/} (no scenes/$name.toml)"
  fi
done

# What each backend scores against the new goldens: the "measured" half of
# each tolerance. PSNR inf means bit-identical.
echo
printf '%-12s %-8s %10s %12s\n' scene backend "psnr (dB)" "max abs"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .toml)
  for be in egl osmesa; do
    "$bin" render "$scene" -o "$tmp/$name.$be.png" --size "$size" --backend "$be" >/dev/null
    json=$("$bin" compare "$golden_dir/$name.png" "$tmp/$name.$be.png" --json 2>/dev/null || true)
    psnr=$(sed -n 's/^  "psnr": \(.*\),$/\1/p' <<<"$json")
    max=$(sed -n 's/^  "max": \(.*\),$/\1/p' <<<"$json")
    [[ $psnr == null ]] && psnr=inf
    printf '%-12s %-8s %10s %12s\n' "$name" "$be" "$psnr" "$max"
  done
done
echo
echo "Now: check the tolerances in tests/golden/suite.toml still hold with margin (it covers every scene),"
echo "add a cost case for a new scene to tests/cost/suite.toml, look at docs/gallery.md (one entry per"
echo "scene), and commit tests/golden, tests/cost and docs/images/gallery."
