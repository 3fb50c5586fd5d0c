#include "importers/shadertoy.h"

#include <algorithm>
#include <string>
#include <system_error>

#include "core/error.h"
#include "io/input_file.h"
#include "importers/es_compat.h"
#include "preprocess/glsl_scan.h"
#include "importers/glslviewer.h"
#include "importers/project_json.h"
#include "io/json_doc.h"
#include "importers/vscode.h"

namespace ms {

namespace fs = std::filesystem;

namespace {

// Shadertoy's uniform set, spelled as on shadertoy.com so shaders paste in
// unchanged; each channel declared as what is bound to it.
std::string wrapper_head(const ProjectPass& pass) {
  std::string s =
      "#version 450 core\n"
      "#define HW_PERFORMANCE 1                 // as on a desktop browser\n"
      "uniform vec3      iResolution;           // viewport, pixels (z = 1)\n"
      "uniform float     iTime;                 // seconds\n"
      "uniform float     iTimeDelta;\n"
      "uniform float     iFrameRate;\n"
      "uniform int       iFrame;\n"
      "uniform vec4      iMouse;\n"
      "uniform vec4      iDate;                 // year, month, day, seconds\n"
      "uniform float     iSampleRate;\n"
      "uniform float     iChannelTime[4];\n"
      "uniform vec3      iChannelResolution[4];\n";
  // One line per channel whatever its type, so the wrapper's line count,
  // and with it the #line mapping of errors, never depends on the bindings.
  for (size_t c = 0; c < pass.inputs.size(); ++c)
    s += std::string("uniform ") + glsl_sampler_type(channel_type(pass.inputs[c].kind)) + " iChannel" +
         std::to_string(c) + ";\n";
  s += "uniform vec2      uJitter;               // marchstudio: sub-pixel sample position\n"
       "uniform vec2      uPixelOffset;          // marchstudio: a tile's lower-left pixel in the image\n"
       "layout(location = 0) out vec4 outColor;\n"
       // gl_FragCoord in the whole image, also in a tile's framebuffer
       // (render/tiled_still.h): main() sets it before mainImage runs. The
       // initialiser keeps a read in a function above main() from warning
       // of a name that is ours.
       "vec4 msFragCoord = vec4(0.0);\n"
       "#define gl_FragCoord msFragCoord\n";
  return s;
}

// The Image pass: Shadertoy's canvas takes (rgb, 1), each channel converted
// on its own as a float-to-unorm write does (NaN 0, +Inf 1, -Inf 0), so a
// NaN in one channel leaves the others. A negative alpha marks the sample
// for the host's NaN/Inf count (--strict); the post pass and the host
// restore alpha 1.
const char* image_main() {
  return "#undef gl_FragCoord\n"
         "float msUnorm(float v) { return isnan(v) ? 0.0 : isinf(v) ? (v > 0.0 ? 1.0 : 0.0) : v; }\n"
         "void main() {\n"
         "  vec4 c = vec4(0.0, 0.0, 0.0, 1.0);\n"
         "  msFragCoord = vec4(gl_FragCoord.xy + uPixelOffset, gl_FragCoord.zw);\n"
         "  mainImage(c, floor(gl_FragCoord.xy) + uPixelOffset + uJitter);\n"
         "  bool bad = any(isnan(c.rgb)) || any(isinf(c.rgb));\n"
         "  outColor = vec4(msUnorm(c.r), msUnorm(c.g), msUnorm(c.b), bad ? -4096.0 : 1.0);\n"
         "}\n";
}

// A buffer pass: the whole vec4 into the RGBA32F buffer, as it is (a NaN
// stays a NaN there, as on Shadertoy), at pixel centres.
const char* buffer_main() {
  return "#undef gl_FragCoord\n"
         "void main() {\n"
         "  vec4 c = vec4(0.0, 0.0, 0.0, 1.0);\n"
         "  msFragCoord = gl_FragCoord;\n"
         "  mainImage(c, gl_FragCoord.xy);\n"
         "  outColor = c;\n"
         "}\n";
}

// The Cube A pass: one draw per face (render/cubemap.h), uCubeFace 0..5 in
// GL's order +X, -X, +Y, -Y, +Z, -Z. rayDir goes through the pixel's centre
// on the face of the cube [-1, 1]^3, as GL's cube map table (and
// Shadertoy's corners) put it, so texture(cube, rayDir) reads this pixel;
// rayOri is the origin. The whole vec4 into the RGBA16F face.
const char* cube_main() {
  return "#undef gl_FragCoord\n"
         "uniform int uCubeFace;                   // marchstudio: the face drawn, 0..5\n"
         "void main() {\n"
         "  vec4 c = vec4(0.0, 0.0, 0.0, 1.0);\n"
         "  msFragCoord = gl_FragCoord;\n"
         "  vec2 q = 2.0 * gl_FragCoord.xy / iResolution.xy - 1.0;  // (sc, tc)\n"
         "  vec3 d = uCubeFace == 0 ? vec3(1.0, -q.y, -q.x) : uCubeFace == 1 ? vec3(-1.0, -q.y, q.x)\n"
         "         : uCubeFace == 2 ? vec3(q.x, 1.0, q.y)   : uCubeFace == 3 ? vec3(q.x, -1.0, -q.y)\n"
         "         : uCubeFace == 4 ? vec3(q.x, -q.y, 1.0)  : vec3(-q.x, -q.y, -1.0);\n"
         "  mainCubemap(c, gl_FragCoord.xy, vec3(0.0), normalize(d));\n"
         "  outColor = c;\n"
         "}\n";
}

fs::path absolute_normal(const fs::path& p) {
  std::error_code ec;
  return fs::absolute(p, ec).lexically_normal();
}

// A pass's (or Common's) file, read like an include: inside the roots, a
// regular file. `key` names it in errors.
std::string read_source(const fs::path& file, const std::vector<fs::path>& roots, const std::string& origin,
                        const std::string& key) {
  const fs::path abs = absolute_normal(file);
  if (!within_roots(abs, roots))
    fail_input("'" + display_path(abs) + "' is outside the directories includes may read", origin, 0, key,
               "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
  return read_input_file(abs, "Shadertoy shader", key);
}

void refuse_main(const std::string& code, const std::string& where) {
  const std::string stripped = strip_comments(code);
  if (const size_t at = find_definition(stripped, "main"); at != std::string::npos) {
    const int line =
        1 + static_cast<int>(std::count(stripped.begin(), stripped.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    fail_input("a Shadertoy shader must not define main()", where, line, {},
               "define void mainImage(out vec4 fragColor, in vec2 fragCoord) instead");
  }
}

}  // namespace

bool looks_like_shadertoy(std::string_view source) {
  std::string s = strip_comments(source);
  return find_definition(s, "mainImage") != std::string_view::npos &&
         find_definition(s, "main") == std::string_view::npos;
}

std::vector<fs::path> project_roots(const ShaderProject& p, const AssembleOptions& opts, const fs::path& scene_file) {
  // A bare shader was named on the command line: its real directory is the
  // root, even through a symlink. A wrapped one must lie in its scene's.
  std::error_code ec;
  return include_roots(scene_file.empty() ? fs::weakly_canonical(absolute_normal(p.origin), ec) : scene_file, opts);
}

ShaderProject load_shadertoy_file(const fs::path& file, const AssembleOptions& opts, const fs::path& scene_file) {
  const fs::path abs = absolute_normal(file);
  ShaderProject probe;
  probe.origin = abs;
  const std::vector<fs::path> roots = project_roots(probe, opts, scene_file);
  const std::string key = scene_file.empty() ? "" : "scene.shadertoy";
  if (!within_roots(abs, roots))
    fail_input("the Shadertoy shader '" + display_path(abs) + "' is outside the directories includes may read",
               display_path(scene_file.empty() ? file : scene_file), 0, key,
               "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
  const std::string text = read_input_file(abs, "Shadertoy shader", key);  // regular files only: a FIFO would block
  ShaderProject p;
  if (abs.extension() == ".json" || looks_like_json(text)) {
    p = load_shadertoy_json(text, display_path(abs));
  } else if (looks_like_vscode(text)) {
    p = load_vscode(text, abs, roots);
  } else if (looks_like_glslviewer(text)) {
    p = load_glslviewer(text, abs);
  } else {
    ProjectPass image;
    image.kind = PassKind::image;
    image.name = "Image";
    image.file = abs;
    image.where = display_path(abs);
    p.passes.push_back(std::move(image));
  }
  p.origin = abs;
  if (p.name.empty()) p.name = abs.stem().string();
  return p;
}

ShaderSource assemble_shadertoy_pass(const ShaderProject& p, size_t index, const AssembleOptions& opts,
                                     const fs::path& scene_file) {
  const ProjectPass& pass = p.passes.at(index);
  const std::vector<fs::path> roots = project_roots(p, opts, scene_file);
  if (p.glslviewer) return assemble_glslviewer_pass(p, index, opts, roots);
  const std::string origin = display_path(scene_file.empty() ? p.origin : scene_file);
  PreprocessOptions popts;
  popts.include_dirs = {opts.shader_dir};
  popts.roots = roots;
  std::vector<fs::path> read;  // the files besides includes that this pass depends on
  read.push_back(absolute_normal(p.origin));

  std::string root = wrapper_head(pass);
  for (const auto& [name, value] : opts.defines) root += "#define " + name + " " + value + "\n";
  // A tab's code, inline (JSON) or from its file, as one of the root's includes.
  const auto add_tab = [&](const std::string& inline_code, const fs::path& file, std::string where,
                           const std::string& what, const std::string& include, std::string& code) {
    code = inline_code;
    fs::path dir = absolute_normal(p.origin).parent_path();
    if (!file.empty()) {
      // A loader that rewrote the file's text (importers/vscode.h) gives both.
      if (code.empty()) code = read_source(file, roots, origin, what);
      where = display_path(file);
      dir = absolute_normal(file).parent_path();
      read.push_back(absolute_normal(file));
    }
    refuse_main(code, where);
    popts.inline_files[include] = {where, rename_desktop_keywords(code), dir};
    root += "#include \"" + include + "\"\n";
    return where;
  };
  std::string common, code;
  if (!p.common.empty() || !p.common_file.empty())
    add_tab(p.common, p.common_file, p.common_where.empty() ? origin + " (Common)" : p.common_where,
            "shadertoy.common", "marchstudio:common", common);
  const std::string where = add_tab(pass.code, pass.file, pass.where.empty() ? origin + " (" + pass.name + ")" : pass.where,
                                    pass.name, "marchstudio:pass", code);
  const fs::path dir = pass.file.empty() ? absolute_normal(p.origin).parent_path() : absolute_normal(pass.file).parent_path();
  root += pass.kind == PassKind::image ? image_main() : pass.kind == PassKind::cube ? cube_main() : buffer_main();

  ShaderSource src = preprocess(root, where + " (shadertoy wrapper)", dir, popts);
  for (const fs::path& f : read)
    if (std::find(src.dependencies.begin(), src.dependencies.end(), f) == src.dependencies.end())
      src.dependencies.insert(src.dependencies.begin(), f);
  // mainImage may come from a file the pass includes, so look after expansion.
  if (pass.kind == PassKind::cube) {
    if (find_definition(strip_comments(src.text), "mainCubemap") == std::string_view::npos)
      fail_input("no mainCubemap() found in the Cube A pass", where, 0, {},
                 "define void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir)");
    return src;
  }
  if (find_definition(strip_comments(src.text), "mainImage") == std::string_view::npos) {
    std::string hint = "define void mainImage(out vec4 fragColor, in vec2 fragCoord)";
    if (find_definition(strip_comments(code), "map", "vec2") != std::string_view::npos && !pass.file.empty()) {
      // A scene's map file handed over by mistake: point at its scene.
      fs::path toml = pass.file;
      toml.replace_extension(".toml");
      std::error_code ec;
      hint = fs::is_regular_file(toml, ec) ? "it defines map(): render its scene, " + display_path(toml)
                                           : "it defines map(): a map file is rendered through a scene .toml whose "
                                             "[scene] map names it (docs/scene-format.md)";
    }
    fail_input("no mainImage() found in the Shadertoy shader", where, 0, {}, hint);
  }
  return src;
}

ShaderSource assemble_shadertoy(const fs::path& glsl_file, const AssembleOptions& opts, const fs::path& scene_file) {
  const ShaderProject p = load_shadertoy_file(glsl_file, opts, scene_file);
  return assemble_shadertoy_pass(p, p.passes.size() - 1, opts, scene_file);
}

}  // namespace ms
