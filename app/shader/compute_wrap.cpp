#include "shader/compute_wrap.h"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include "core/error.h"
#include "preprocess/log_map.h"

namespace ms {

std::string group_name(const ComputeGroup& g) {
  std::string s = std::to_string(g.x) + "x" + std::to_string(g.y);
  if (g.stripe > 0) s += "/" + std::to_string(g.stripe);
  return s;
}

std::optional<ComputeGroup> parse_group_name(const std::string& text) {
  ComputeGroup g;
  char x = 0, slash = 0, extra = 0;
  const int n = std::sscanf(text.c_str(), "%d%c%d%c%d%c", &g.x, &x, &g.y, &slash, &g.stripe, &extra);
  if ((n != 3 && n != 5) || (x != 'x' && x != 'X') || (n == 5 && slash != '/') || g.x < 1 || g.y < 1 ||
      g.x * g.y > 1024 || g.stripe < 0 || g.stripe > 1024)
    return std::nullopt;
  return g;
}

namespace {

// The text with comments blanked (newlines kept), for scans that must not
// see what a comment says.
std::string strip_comments(const std::string& s) {
  std::string out = s;
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n') out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      i += 2;
      while (i + 1 < out.size() && !(out[i] == '*' && out[i + 1] == '/')) {
        if (out[i] != '\n') out[i] = ' ';
        ++i;
      }
      if (i + 1 < out.size()) out[i] = out[i + 1] = ' ';
      ++i;
    }
  }
  return out;
}

const std::regex& derivative_re() {
  static const std::regex re(R"(\b(dFdx|dFdy|fwidth)(Fine|Coarse)?\s*\()");
  return re;
}

// The file:line of byte `pos` of the assembled text, by the last #line
// directive before it (preprocess/preprocess.h's encoding, log_map.h decodes it).
SourceLocation location_at(const ShaderSource& src, size_t pos) {
  static const std::regex line_re(R"((^|\n)#line\s+([0-9]+)(\s+([0-9]+))?[^\n]*\n)");
  long long line = 1, string_no = 0;
  size_t from = 0;
  const auto end = src.text.begin() + static_cast<std::ptrdiff_t>(std::min(pos, src.text.size()));
  for (auto it = std::sregex_iterator(src.text.begin(), end, line_re); it != std::sregex_iterator(); ++it) {
    line = std::stoll((*it)[2].str());
    string_no = (*it)[4].matched ? std::stoll((*it)[4].str()) : 0;
    from = static_cast<size_t>(it->position() + it->length());
  }
  line += std::count(src.text.begin() + static_cast<std::ptrdiff_t>(from), end, '\n');
  SourceLocation at = map_location(src, string_no, line);
  if (at.file.empty() && !src.files.empty()) at.file = src.files[0];
  return at;
}

// Where the ')' closing the call whose '(' is at `open` is, and where each
// argument after the first starts (after its comma): npos when unbalanced.
size_t close_of(const std::string& scan, size_t open, std::vector<size_t>& arg_starts) {
  int depth = 0;
  for (size_t i = open; i < scan.size(); ++i) {
    const char c = scan[i];
    if (c == '(' || c == '[') ++depth;
    else if (c == ')' || c == ']') {
      if (--depth == 0) return i;
    } else if (c == ',' && depth == 1) arg_starts.push_back(i + 1);
  }
  return std::string::npos;
}

// One replacement in the source: `len` bytes at `pos` become `with`.
struct Edit {
  size_t pos, len;
  std::string with;
};

// What no wrapper can fix, refused before any edit: a derivative call, a
// work group of no or too many invocations.
void check_computable(const ShaderSource& frag, const std::string& scan, ComputeGroup group) {
  std::smatch dm;
  if (std::regex_search(scan, dm, derivative_re())) {
    const SourceLocation at = location_at(frag, static_cast<size_t>(dm.position()));
    fail_input("--dispatch compute: the shader calls " + dm[1].str() + dm[2].str() +
                   "(), which a compute shader cannot",
               at.file, at.line, "--dispatch",
               "render it with --dispatch fragment, or take the footprint from ray differentials");
  }
  if (group.x < 1 || group.y < 1 || group.x * group.y > 1024)
    fail_input("--compute-group " + std::to_string(group.x) + "x" + std::to_string(group.y) +
                   " must have 1..1024 invocations",
               {}, 0, "--compute-group");
}

// The outputs become plain variables, main() msSceneMain(), gl_FragCoord
// the invocation's pixel. Returns how many main()s there were.
int fragment_edits(const std::string& scan, std::vector<Edit>& edits) {
  static const std::regex out_re(R"(layout\s*\(\s*location\s*=\s*([0-9]+)\s*\)\s*out\s+vec4\s+(\w+)\s*;)");
  static const std::regex main_re(R"(\bvoid\s+main\s*\(\s*(void)?\s*\))");
  static const std::regex coord_re(R"(\bgl_FragCoord\b)");
  for (auto it = std::sregex_iterator(scan.begin(), scan.end(), out_re); it != std::sregex_iterator(); ++it)
    edits.push_back({static_cast<size_t>(it->position()), static_cast<size_t>(it->length()),
                     "vec4 " + (*it)[2].str() + " = vec4(0.0);"});
  int mains = 0;
  for (auto it = std::sregex_iterator(scan.begin(), scan.end(), main_re); it != std::sregex_iterator(); ++it, ++mains)
    edits.push_back({static_cast<size_t>(it->position()), static_cast<size_t>(it->length()), "void msSceneMain()"});
  for (auto it = std::sregex_iterator(scan.begin(), scan.end(), coord_re); it != std::sregex_iterator(); ++it)
    edits.push_back({static_cast<size_t>(it->position()), static_cast<size_t>(it->length()), "msComputeCoord"});
  return mains;
}

// Implicit-LOD lookups take their LOD from derivatives, which a compute
// shader lacks: each becomes its explicit-LOD form at LOD 0. On textures of
// one level whose samplers minify and magnify alike (every non-mipmapped
// input, render/graph.cpp) that is the same texel; with a mip chain it is
// not, so a pass with a mipmapped input is refused instead.
void lod_edits(const ShaderSource& frag, const std::string& scan, bool mipmapped_inputs, std::vector<Edit>& edits) {
  static const std::regex tex_re(R"(\b(texture|textureOffset|textureProj|textureProjOffset)\s*\()");
  for (auto it = std::sregex_iterator(scan.begin(), scan.end(), tex_re); it != std::sregex_iterator(); ++it) {
    const size_t pos = static_cast<size_t>(it->position());
    const std::string name = (*it)[1].str();
    std::vector<size_t> args;
    const size_t close = close_of(scan, pos + static_cast<size_t>(it->length()) - 1, args);
    if (mipmapped_inputs || close == std::string::npos) {
      const SourceLocation at = location_at(frag, pos);
      fail_input("--dispatch compute: " + name + "() takes its mip level from derivatives, which a compute shader " +
                     (close == std::string::npos ? "lacks" : "lacks, and this pass has a mipmapped input"),
                 at.file, at.line, "--dispatch", "render it with --dispatch fragment, or call textureLod()");
    }
    const bool offset = name == "textureOffset" || name == "textureProjOffset";
    const std::string base = name == "texture" || name == "textureOffset" ? "textureLod" : "textureProjLod";
    edits.push_back({pos, name.size(), offset ? base + "Offset" : base});
    if (offset && args.size() >= 2) edits.push_back({args[1], 0, " 0.0,"});  // (s, P, lod, offset)
    else if (!offset && args.size() == 1) edits.push_back({close, 0, ", 0.0"});
    // (s, P, bias): the bias is the LOD, which on one level picks level 0 too.
  }
}

// `text` with the edits made, in text order.
std::string apply_edits(const std::string& text, std::vector<Edit> edits) {
  std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.pos < b.pos; });
  std::string out;
  out.reserve(text.size() + 2048);
  size_t at = 0;
  for (const Edit& e : edits) {
    out.append(text, at, e.pos - at);
    out += e.with;
    at = e.pos + e.len;
  }
  out.append(text, at, std::string::npos);
  return out;
}

// After the fragment source: main() runs the scene's for one invocation's
// pixel and stores (or adds) its outputs.
const char* const kEpilogue =
      "\n// ---- marchstudio: the compute wrapper (shader/compute_wrap.h) ----\n"
      "layout(local_size_x = MS_GROUP_X, local_size_y = MS_GROUP_Y) in;\n"
      "layout(rgba32f, binding = 0) uniform image2D msOut0;\n"
      "#ifndef AOV_OUTPUTS\n"
      "#define AOV_OUTPUTS 0  // a Shadertoy pass: colour only\n"
      "#endif\n"
      "#if AOV_OUTPUTS\n"
      "layout(rgba32f, binding = 1) uniform image2D msOut1;\n"
      "layout(rgba32f, binding = 2) uniform image2D msOut2;\n"
      "layout(rgba32f, binding = 3) uniform image2D msOut3;\n"
      "#endif\n"
      "uniform ivec4 uMsRect;       // the tile: lower-left pixel, width, height (framebuffer pixels)\n"
      "uniform int uMsAccumulate;   // 1: add to what the images hold (the fragment path's blending)\n"
      "#if MS_STRIPE > 0\n"
      "uniform ivec2 uMsGroups;     // the tile's work groups, x by y, dispatched as one row\n"
      "// Group i of the row, in stripes of MS_STRIPE group rows, each walked\n"
      "// column by column: groups that run together cover a compact patch.\n"
      "ivec2 msGroup() {\n"
      "  int i = int(gl_WorkGroupID.x), per = MS_STRIPE * uMsGroups.x, s = i / per, k = i - s * per;\n"
      "  int rows = min(MS_STRIPE, uMsGroups.y - s * MS_STRIPE);\n"
      "  return ivec2(k / rows, s * MS_STRIPE + k % rows);\n"
      "}\n"
      "#else\n"
      "ivec2 msGroup() { return ivec2(gl_WorkGroupID.xy); }\n"
      "#endif\n"
      "void main() {\n"
      "  ivec2 local = msGroup() * ivec2(MS_GROUP_X, MS_GROUP_Y) + ivec2(gl_LocalInvocationID.xy);\n"
      "  if (local.x >= uMsRect.z || local.y >= uMsRect.w) return;\n"
      "  ivec2 px = uMsRect.xy + local;\n"
      "  msComputeCoord = vec4(vec2(px) + 0.5, 0.0, 1.0);\n"
      "  msSceneMain();\n"
      "  vec4 c0 = outColor;\n"
      "  if (uMsAccumulate != 0) c0 = c0 + imageLoad(msOut0, px);\n"
      "  imageStore(msOut0, px, c0);\n"
      "#if AOV_OUTPUTS\n"
      "  vec4 c1 = outGeom, c2 = outMisc, c3 = outCost;\n"
      "  if (uMsAccumulate != 0) {\n"
      "    c1 = c1 + imageLoad(msOut1, px);\n"
      "    c2 = c2 + imageLoad(msOut2, px);\n"
      "    c3 = c3 + imageLoad(msOut3, px);\n"
      "  }\n"
      "  imageStore(msOut1, px, c1);\n"
      "  imageStore(msOut2, px, c2);\n"
      "  imageStore(msOut3, px, c3);\n"
      "#endif\n"
      "}\n";

}  // namespace

std::string first_derivative_call(const std::string& glsl) {
  const std::string text = strip_comments(glsl);
  std::smatch m;
  if (std::regex_search(text, m, derivative_re())) return m[1].str() + m[2].str();
  return {};
}

ShaderSource wrap_compute(const ShaderSource& frag, ComputeGroup group, bool mipmapped_inputs) {
  const std::string what = frag.files.empty() ? std::string() : frag.files[0];
  // Comments blanked in a copy of the same length: the matches' positions
  // hold in the original text.
  const std::string scan = strip_comments(frag.text);
  check_computable(frag, scan, group);
  std::vector<Edit> edits;
  const int mains = fragment_edits(scan, edits);
  lod_edits(frag, scan, mipmapped_inputs, edits);
  if (mains != 1) fail_input("--dispatch compute: the shader has no single main()", what, 0, "--dispatch");
  std::string text = apply_edits(frag.text, std::move(edits));

  // The prologue after #version (then #line 2 0: source 0's lines stay where
  // they were), the epilogue at the end.
  const size_t eol = text.find('\n');
  if (text.compare(0, 8, "#version") != 0 || eol == std::string::npos)
    fail_input("--dispatch compute: the shader does not start with #version", what, 0, "--dispatch");
  const std::string prologue =
      "#define MS_COMPUTE 1\n"
      "#define MS_GROUP_X " + std::to_string(group.x) + "\n"
      "#define MS_GROUP_Y " + std::to_string(group.y) + "\n"
      "#define MS_STRIPE " + std::to_string(group.stripe) + "\n"
      "vec4 msComputeCoord;  // the fragment coordinate of the invocation's pixel\n"
      "#line 2 0\n";
  text.insert(eol + 1, prologue);
  text += kEpilogue;
  ShaderSource out = frag;
  out.text = std::move(text);
  return out;
}

}  // namespace ms
