#include "importers/glslviewer.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/error.h"
#include "preprocess/directive.h"
#include "preprocess/confine.h"
#include "importers/es_compat.h"
#include "preprocess/glsl_scan.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The identifiers and punctuation of one line, in order.
std::vector<std::string> tokens(std::string_view line) {
  std::vector<std::string> out;
  for (size_t i = 0; i < line.size();) {
    if (std::isspace(static_cast<unsigned char>(line[i]))) { ++i; continue; }
    size_t j = i;
    while (j < line.size() && ident_char(line[j])) ++j;
    if (j == i) ++j;
    out.emplace_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}


// N of "PREFIX<N>" (digits only), or -1.
int suffix_number(const std::string& name, std::string_view prefix) {
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string digits = name.substr(prefix.size());
  if (digits.size() > 2 || !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return -1;
  return std::stoi(digits);
}

bool starts_with(const std::string& s, std::string_view p) { return s.compare(0, p.size(), p) == 0; }

// glslViewer uniforms that need what marchstudio does not have: a 3D
// scene (camera, lights, models' render passes), cubemaps, pyramids, floods.
std::string unsupported_uniform(const std::string& name) {
  if (starts_with(name, "u_camera") || name == "u_normalMatrix" || name == "u_inverseViewMatrix" ||
      name == "u_inverseProjectionMatrix")
    return "glslViewer's camera uniforms come with a 3D model, which marchstudio does not load";
  if (starts_with(name, "u_light")) return "glslViewer's lights come with a 3D model, which marchstudio does not load";
  if (starts_with(name, "u_scene") && name != "u_scene")
    return "glslViewer's scene depth and scene buffers come with a 3D model, which marchstudio does not load";
  if (name == "u_cubeMap" || name == "u_SH" || name == "u_iblLuminance")
    return "glslViewer's environment cubemap (-C, -sh) is not run";
  if (starts_with(name, "u_pyramid")) return "glslViewer's convolution pyramids are not run";
  if (starts_with(name, "u_flood")) return "glslViewer's jump-flood passes are not run";
  return {};
}

// Conditionals on these names select passes marchstudio does not run.
std::string unsupported_define(const std::string& name) {
  if (starts_with(name, "PYRAMID_") || starts_with(name, "CONVOLUTION_PYRAMID"))
    return "glslViewer's convolution pyramids are not run";
  if (starts_with(name, "FLOOD_")) return "glslViewer's jump-flood passes are not run";
  if (starts_with(name, "SCENE_BUFFER_")) return "glslViewer's scene buffers come with a 3D model, which marchstudio does not load";
  return {};
}

struct Scan {
  std::set<int> buffers, doubles;          // N of BUFFER_N, DOUBLE_BUFFER_N conditionals
  std::vector<std::pair<std::string, int>> samplers;  // sampler2D names declared, with their lines
  std::vector<std::pair<std::string, std::string>> varyings;  // name, type
  bool postprocessing = false;             // an #ifdef POSTPROCESSING block: main draws u_scene, then this pass
  int scene_line = 0;                      // where u_scene is declared (0: it is not)
};

Scan scan(const std::string& text, const std::string& where) {
  const std::vector<std::string> raw = line_strings(text);
  const std::vector<std::string> lines = line_strings(strip_comments(text));
  Scan s;
  const auto fail = [&](int line, const std::string& name, const std::string& what, const std::string& hint = {}) {
    fail_input(name + ": " + what, where, line, {}, hint.empty() ? "docs/glslviewer.md lists what runs" : hint);
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const std::vector<std::string> t = tokens(lines[i]);
    if (t.empty()) continue;
    if (t[0] == "#" && t.size() > 1) {
      if (t[1] == "version" && t.size() > 2 && t[2] != "100" && t[2] != "110" && t[2] != "120")
        fail(line, "#version " + t[2], "only glslViewer's GLSL 1.x form (gl_FragColor, texture2D, varying) runs",
             "drop the #version line and write gl_FragColor");
      if (t[1] == "if" || t[1] == "ifdef" || t[1] == "ifndef" || t[1] == "elif")
        for (size_t k = 2; k < t.size(); ++k) {
          if (const int n = suffix_number(t[k], "BUFFER_"); n >= 0) s.buffers.insert(n);
          if (const int n = suffix_number(t[k], "DOUBLE_BUFFER_"); n >= 0) s.doubles.insert(n);
          if (t[k] == "POSTPROCESSING") s.postprocessing = true;
          if (const std::string why = unsupported_define(t[k]); !why.empty()) fail(line, t[k], why);
        }
      continue;
    }
    for (size_t k = 0; k < t.size(); ++k) {
      if (t[k] == "attribute") fail(line, "attribute", "a vertex shader's input: marchstudio runs fragment shaders only");
      if (t[k] == "varying" && k + 2 < t.size()) {
        size_t at = k + 1;
        while (at + 1 < t.size() && (t[at] == "lowp" || t[at] == "mediump" || t[at] == "highp")) ++at;
        const std::string& type = t[at];
        const std::string& name = t[at + 1];
        const bool known = (name == "v_texcoord" && type == "vec2") || (name == "v_position" && type == "vec4") ||
                           (name == "v_normal" && type == "vec3") || (name == "v_color" && (type == "vec3" || type == "vec4"));
        if (!known)
          fail(line, name, "not a varying glslViewer's 2D vertex shader writes",
               "it writes vec4 v_position, vec3 v_color, vec3 v_normal, vec2 v_texcoord");
        s.varyings.emplace_back(name, type);
      }
      if (t[k] != "uniform" || k + 2 >= t.size()) continue;
      size_t at = k + 1;
      while (at + 1 < t.size() && (t[at] == "lowp" || t[at] == "mediump" || t[at] == "highp")) ++at;
      const std::string& type = t[at];
      for (size_t n = at + 1; n < t.size() && t[n] != ";"; ++n) {
        if (t[n] == "," || !ident_char(t[n][0])) continue;
        const std::string& name = t[n];
        if (const std::string why = unsupported_uniform(name); !why.empty()) fail(line, name, why);
        if (type == "samplerCube") fail(line, name, "cubemap samplers are not run in a glslViewer shader");
        if (name == "u_scene" && !s.scene_line) s.scene_line = line;
        if (type != "sampler2D") continue;
        // glslViewer sizes a buffer from a trailing "// 512x512" comment; ours are the image's size.
        const std::string& r = raw[i];
        const size_t slash = r.find("//");
        if ((starts_with(name, "u_buffer") || starts_with(name, "u_doubleBuffer")) && slash != std::string::npos &&
            r.find_first_of("0123456789", slash) != std::string::npos)
          fail(line, name, "a buffer with its own size: marchstudio's buffers are the image's size",
               "drop the size comment");
        if (std::none_of(s.samplers.begin(), s.samplers.end(), [&](const auto& d) { return d.first == name; }))
          s.samplers.emplace_back(name, line);
      }
    }
  }
  if (s.scene_line && !s.postprocessing)
    fail(s.scene_line, "u_scene", "glslViewer draws u_scene only for a POSTPROCESSING pass, and this file has none",
         "read u_scene inside #ifdef POSTPROCESSING");
  return s;
}

}  // namespace

bool looks_like_glslviewer(std::string_view source) {
  const std::string s = strip_comments(source);
  if (find_definition(s, "main") == std::string::npos || find_definition(s, "mainImage") != std::string::npos)
    return false;
  for (const std::string& t : tokens(s))
    if (t == "gl_FragColor" || t == "gl_FragData" || (starts_with(t, "u_") && t.size() > 2)) return true;
  return false;
}

ShaderProject load_glslviewer(const std::string& text, const fs::path& file) {
  const std::string where = display_path(file);
  const Scan s = scan(text, where);
  const int nb = static_cast<int>(s.buffers.size()), nd = static_cast<int>(s.doubles.size());
  // glslViewer runs BUFFER_0..BUFFER_{n-1} for n distinct numbers: a gap leaves a block that never runs.
  for (const auto& [set, prefix] : {std::pair{&s.buffers, "BUFFER_"}, std::pair{&s.doubles, "DOUBLE_BUFFER_"}})
    if (!set->empty() && *set->rbegin() >= static_cast<int>(set->size()))
      fail_input(std::string(prefix) + std::to_string(*set->rbegin()) + ": buffers must be numbered from 0 without gaps",
                 where, 0, {}, "glslViewer runs " + std::string(prefix) + "0.." + std::to_string(set->size() - 1) +
                                   " only, so this block would never run");
  const int scene = s.postprocessing ? nb + nd : -1;  // the buffer main draws for POSTPROCESSING to read as u_scene
  if (nb + nd + (s.postprocessing ? 1 : 0) > 4)
    fail_input(std::to_string(nb) + " buffers and " + std::to_string(nd) + " double buffers" +
                   (s.postprocessing ? " and the POSTPROCESSING scene" : "") + ": marchstudio runs at most 4",
               where, 0, {}, "BUFFER_N, DOUBLE_BUFFER_N and u_scene share Shadertoy's four buffers, A..D");
  ShaderProject p;
  p.glslviewer = true;
  p.origin = file;
  p.name = file.stem().string();
  // glslViewer's order: every BUFFER_N, then every DOUBLE_BUFFER_N, then main.
  const auto pass = [&](PassKind kind, int output, const std::string& define) {
    ProjectPass ps;
    ps.kind = kind;
    ps.output = output;
    ps.define = define;
    ps.name = define.empty() ? "main" : define;
    ps.file = file;
    ps.code = text;  // read once; every pass compiles the same text
    ps.where = where;
    size_t c = 0;
    for (const auto& [name, line] : s.samplers) {
      ProjectInput in;
      in.uniform = name;
      if (const int b = suffix_number(name, "u_buffer"); b >= 0) {
        if (b >= nb) fail_input(name + ": no #ifdef BUFFER_" + std::to_string(b) + " block draws it", where, line, {});
        if (b != output) in.kind = InputKind::buffer, in.buffer = b;  // glslViewer never binds a buffer to itself
      } else if (name == "u_scene") {
        if (define == "POSTPROCESSING") in.kind = InputKind::buffer, in.buffer = scene;  // main's image, this frame's
      } else if (const int d = suffix_number(name, "u_doubleBuffer"); d >= 0) {
        if (d >= nd) fail_input(name + ": no #ifdef DOUBLE_BUFFER_" + std::to_string(d) + " block draws it", where, line, {});
        in.kind = InputKind::buffer, in.buffer = nb + d;
      }
      in.sampler = {TexFilter::linear, TexWrap::clamp, false, false};
      if (c == 4)
        fail_input(name + ": a fifth sampler2D; marchstudio binds at most 4 per shader", where, line, {},
                   "Shadertoy's four channels; drop a texture or buffer");
      ps.inputs[c++] = in;
    }
    p.passes.push_back(std::move(ps));
  };
  for (int b = 0; b < nb; ++b) pass(PassKind::buffer, b, "BUFFER_" + std::to_string(b));
  for (int d = 0; d < nd; ++d) pass(PassKind::buffer, nb + d, "DOUBLE_BUFFER_" + std::to_string(d));
  // With POSTPROCESSING, main draws into the scene buffer and the same file
  // with POSTPROCESSING defined draws the image from it, as glslViewer does.
  if (s.postprocessing) {
    pass(PassKind::buffer, scene, "");
    pass(PassKind::image, -1, "POSTPROCESSING");
  } else {
    pass(PassKind::image, -1, "");
  }
  check_project(p, where);
  return p;
}

void bind_glslviewer_textures(ShaderProject& p, const std::vector<NamedTexture>& textures,
                              std::vector<std::string>& warnings) {
  if (textures.empty()) return;
  if (!p.glslviewer)
    fail_input("--texture has no effect on " + display_path(p.origin), {}, 0, "--texture",
               "it binds a glslViewer shader's u_tex0..; a Shadertoy shader names its textures itself");
  for (const NamedTexture& t : textures) {
    bool bound = false;
    for (ProjectPass& pass : p.passes)
      for (ProjectInput& in : pass.inputs)
        if (in.uniform == t.name && in.kind == InputKind::none) {
          in.kind = InputKind::texture;
          in.src = t.file.string();
          in.file = t.file;
          // glslViewer's textures: linear, repeat, flipped so the picture is upright in v_texcoord.
          in.sampler = {TexFilter::linear, TexWrap::repeat, true, false};
          bound = true;
        }
    if (!bound) warnings.push_back("--texture " + t.name + "=" + t.file.string() + ": the shader declares no sampler2D " + t.name);
  }
}

ShaderSource assemble_glslviewer_pass(const ShaderProject& p, size_t index, const AssembleOptions& opts,
                                      const std::vector<fs::path>& roots) {
  const ProjectPass& pass = p.passes.at(index);
  const Scan s = scan(pass.code, pass.where);
  // GLSL 1.x on #version 450 core; the user's main() runs inside ours.
  std::string root =
      "#version 450 core\n"
      "#define GLSLVIEWER 300\n"
      "#define PLATFORM_LINUX\n";
  if (!pass.define.empty()) root += "#define " + pass.define + "\n";
  for (const auto& [name, value] : opts.defines) root += "#define " + name + " " + value + "\n";
  root +=
      "uniform vec3 iResolution;\n"
      "uniform vec2 uJitter;\n"
      "uniform vec2 uPixelOffset;\n"
      "layout(location = 0) out vec4 outColor;\n"
      // Initialised here, not only in main(), which comes after the user's
      // functions: a read there must not warn of these names, which are ours.
      "vec4 msFragColor = vec4(0.0);\n"
      "vec4 msFragData[4] = vec4[4](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));\n"  // [0] is the pass's colour
      "vec4 msFragCoord = vec4(0.0);\n"
      "#define varying\n"
      "#define texture2D texture\n"
      "#define texture2DProj textureProj\n"
      "#define texture2DLod textureLod\n"
      "#define gl_FragColor msFragColor\n"
      "#define gl_FragData msFragData\n"
      "#define gl_FragCoord msFragCoord\n"
      "#define main msGlslViewerMain\n"
      "#include \"marchstudio:pass\"\n"
      "#undef main\n"
      "#undef gl_FragCoord\n"
      "#undef gl_FragColor\n"
      "#undef gl_FragData\n"
      "float msUnorm(float v) { return isnan(v) ? 0.0 : isinf(v) ? (v > 0.0 ? 1.0 : 0.0) : v; }\n"
      "void main() {\n";
  const bool image = pass.kind == PassKind::image;
  // gl_FragCoord in the whole image (tiles) at the sample's position (spp); buffers at pixel centres.
  root += image ? "  msFragCoord = vec4(floor(gl_FragCoord.xy) + uPixelOffset + uJitter, gl_FragCoord.zw);\n"
                : "  msFragCoord = gl_FragCoord;\n";
  // What glslViewer's billboard vertex shader interpolates, at this fragment.
  for (const auto& [name, type] : s.varyings) {
    if (name == "v_texcoord") root += "  v_texcoord = msFragCoord.xy / iResolution.xy;\n";
    if (name == "v_position") root += "  v_position = vec4(msFragCoord.xy / iResolution.xy * 2.0 - 1.0, 0.0, 1.0);\n";
    if (name == "v_color") root += "  v_color = " + type + "(1.0);\n";
    if (name == "v_normal") root += "  v_normal = vec3(0.0, 0.0, 1.0);\n";
  }
  root += "  msGlslViewerMain();\n";
  const std::vector<std::string> words = tokens(strip_comments(pass.code));
  if (std::find(words.begin(), words.end(), "gl_FragData") != words.end()) root += "  msFragColor = msFragData[0];\n";
  // The main pass as Shadertoy's Image pass writes (one home for the
  // non-finite rules: importers/shadertoy.cpp); buffers keep the whole vec4.
  root += image ? "  vec4 c = msFragColor;\n"
                  "  bool bad = any(isnan(c.rgb)) || any(isinf(c.rgb));\n"
                  "  outColor = vec4(msUnorm(c.r), msUnorm(c.g), msUnorm(c.b), bad ? -4096.0 : 1.0);\n"
                : "  outColor = msFragColor;\n";
  root += "}\n";

  // A GLSL 1.x #version line is ours to give: blanked, so lines stay.
  std::string code = pass.code;
  std::vector<std::string> lines = line_strings(code);
  code.clear();
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::vector<std::string> t = tokens(lines[i]);
    if (t.size() > 1 && t[0] == "#" && t[1] == "version") lines[i].clear();
    code += lines[i] + (i + 1 < lines.size() ? "\n" : "");
  }
  PreprocessOptions popts;
  popts.include_dirs = {opts.shader_dir};
  popts.roots = roots;
  const fs::path dir = pass.file.parent_path();
  popts.inline_files["marchstudio:pass"] = {pass.where, rename_desktop_keywords(code), dir};
  ShaderSource src = preprocess(root, pass.where + " (glslviewer wrapper)", dir, popts);
  if (std::find(src.dependencies.begin(), src.dependencies.end(), pass.file) == src.dependencies.end())
    src.dependencies.insert(src.dependencies.begin(), pass.file);
  return src;
}

}  // namespace ms
