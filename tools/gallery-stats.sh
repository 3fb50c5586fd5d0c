#!/usr/bin/env bash
# Measures every scene in scenes/ with `marchstudio bench` and writes the
# table between the <!-- gallery-stats:begin --> and <!-- gallery-stats:end -->
# markers of docs/gallery.md: frame time (wall median of 3 frames after 1
# warm-up, at the scene's own size, spp 1), steps and map() calls per pixel
# (the counting pass: deterministic), compile time, the machine and GL
# renderer, the date; and between <!-- gallery-psnr:begin --> and
# <!-- gallery-psnr:end --> what each scene's fresh render scores against
# its golden on both backends. Rerun it after changing a scene or the tracer.
#
# Usage: tools/gallery-stats.sh [path/to/marchstudio]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin=${1:-${MARCHSTUDIO:-$root/build/marchstudio}}
if [[ ! -x "$bin" ]]; then
  echo "gallery-stats.sh: no marchstudio binary at '$bin' (build it, or pass its path)" >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for scene in "$root"/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  "$bin" bench "$scene" --frames 3 --warmup 1 --json > "$tmp/$name.json"
  echo "measured $name" >&2
done
machine="$(nproc) cores, $(uname -m), $(. /etc/os-release && echo "$PRETTY_NAME")"
/usr/bin/python3 - "$tmp" "$root/docs/gallery.md" "$machine" "$(date -u +%Y-%m-%d)" <<'PY'
import json, os, sys
tmp, doc, machine, date = sys.argv[1:5]
rows, renderer = [], ""
for f in sorted(os.listdir(tmp)):
    j = json.load(open(os.path.join(tmp, f)))
    name = f[:-5]
    c, s = j["cost"], j["settings"]
    renderer = j["machine"]["gl_renderer"]
    rows.append("| [`%s`](#%s) | %dx%d | %.0f | %.0f | %.2f | %.1f | %.2f%% |" % (
        name, name, s["width"], s["height"], j["frame_ms"]["wall"]["median"], j["startup_ms"]["compile_link"],
        c["primary_steps"]["mean"], c["sdf_evals"]["mean"], 100.0 * c["step_cap_fraction"]))
table = ["<!-- gallery-stats:begin -->",
         "Measured by `tools/gallery-stats.sh` on %s, %s, `GL_RENDERER` = `%s`, %s." % (machine, "EGL surfaceless", renderer, date),
         "Frame: wall-clock median of 3 frames (after 1 warm-up) at the scene's size, 1 spp; the machine is shared, so",
         "compare times within one run. Steps and map() calls are per pixel, from bench's counting pass (deterministic).",
         "",
         "| scene | size | frame ms | compile+link ms | primary steps / pixel | map() calls / pixel | pixels at the step cap |",
         "|---|---|---|---|---|---|---|"] + rows + ["<!-- gallery-stats:end -->"]
text = open(doc).read()
b, e = text.index("<!-- gallery-stats:begin -->"), text.index("<!-- gallery-stats:end -->") + len("<!-- gallery-stats:end -->")
open(doc, "w").write(text[:b] + "\n".join(table) + text[e:])
PY
# Each scene rendered again on both backends against its golden, as the
# golden suite does (llvmpipe pinned): the PSNR and max difference it scores.
mesa_vendor=/usr/share/glvnd/egl_vendor.d/50_mesa.json
if [[ -f $mesa_vendor ]]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$mesa_vendor; fi
LIBGL_ALWAYS_SOFTWARE=1 "$bin" test "$root/tests/golden/suite.toml" --json > "$tmp.golden.json" 2>/dev/null || true
/usr/bin/python3 - "$tmp.golden.json" "$root/docs/gallery.md" "$machine" "$(date -u +%Y-%m-%d)" <<'PY'
import json, sys
src, doc, machine, date = sys.argv[1:5]
j = json.load(open(src))
by, renderer, n_same, worst = {}, "", 0, 0
for c in j["cases"]:
    scene, backend = c["name"].rsplit(".", 1)
    chk = [k for k in c["checks"] if k["metric"] == "psnr"][0]
    psnr = "identical" if chk["identical"] else "%.2f dB" % chk["psnr"]
    by.setdefault(scene, {})[backend] = "%s, max %d/255" % (psnr, round(chk["max"] * 255)) + ("" if c["outcome"] == "pass" else " (**%s**)" % c["outcome"])
    renderer = c["gl_renderer"] or renderer
    n_same += 1 if chk["identical"] else 0
    worst = max(worst, round(chk["max"] * 255))
rows = ["<!-- gallery-psnr:begin -->",
        "A fresh render against its golden, as the golden suite scores it (`marchstudio test tests/golden/suite.toml --json`),",
        "measured by `tools/gallery-stats.sh` on %s, `GL_RENDERER` = `%s`, %s." % (machine, renderer, date),
        "%d of the %d renders are bit-identical to their goldens; the largest difference of any pixel is %d/255." % (
            n_same, len(j["cases"]), worst),
        "",
        "| scene | egl | osmesa |", "|---|---|---|"]
rows += ["| `%s` | %s | %s |" % (s, by[s].get("egl", "-"), by[s].get("osmesa", "-")) for s in sorted(by)]
rows.append("<!-- gallery-psnr:end -->")
text = open(doc).read()
b, e = text.index("<!-- gallery-psnr:begin -->"), text.index("<!-- gallery-psnr:end -->") + len("<!-- gallery-psnr:end -->")
open(doc, "w").write(text[:b] + "\n".join(rows) + text[e:])
PY
rm -f "$tmp.golden.json"
echo "wrote the tables in docs/gallery.md" >&2
