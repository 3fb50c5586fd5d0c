#include "gpu_eval.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "scene/features.h"
#include "preprocess/preprocess.h"

namespace ms::test {
namespace {

constexpr int kWidth = 1024;  // texels per row of the point and sample textures
constexpr int kSlots = 4;     // zero crossings kept per ray

// One invocation per point (mode 0), per ray (mode 1) or per uv (mode 2).
const char* kMain = R"GLSL(
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D uPoints;
layout(rgba32f, binding = 0) uniform writeonly image2D uOut;
uniform int uMode, uCount, uGrid, uSteps, uDims;
uniform vec3 uLo, uHi;

ivec2 texel(int i) { return ivec2(i % 1024, i / 1024); }

// Ray r: its axis, then a grid position over the other two axes (dims 2:
// x and y rays in the plane z = 0).
void rayOf(int r, out vec3 o, out vec3 d, out float len) {
  int per = uDims == 2 ? uGrid : uGrid * uGrid;
  int axis = r / per, k = r % per;
  vec3 size = uHi - uLo;
  vec3 cell = (vec3(float(k % uGrid), float(k / uGrid), 0.0) + 0.5) / float(uGrid);
  if (uDims == 2) cell = vec3(cell.x, 0.5, 0.0);
  vec3 pos;
  if (axis == 0) pos = vec3(0.0, cell.x, cell.y);
  else if (axis == 1) pos = vec3(cell.x, 0.0, cell.y);
  else pos = vec3(cell.x, cell.y, 0.0);
  o = uLo + pos * size;
  if (uDims == 2) o.z = 0.0;
  d = vec3(axis == 0, axis == 1, axis == 2);
  len = dot(d, size);
}

void main() {
  int id = int(gl_GlobalInvocationID.x);
  if (id >= uCount) return;
  if (uMode == 0) {
    vec3 p = texelFetch(uPoints, texel(id), 0).xyz;
    imageStore(uOut, texel(id), vec4(caseF(p), caseInside(p) ? 1.0 : 0.0, caseSkip(p) ? 1.0 : 0.0, caseCheck(p)));
  } else if (uMode == 1) {
    vec3 o, d;
    float len;
    rayOf(id, o, d, len);
    float dt = len / float(uSteps - 1);
    int found = 0;
    float t0 = 0.0, f0 = caseF(o);
    for (int s = 1; s < uSteps && found < 4; ++s) {
      float t1 = float(s) * dt, f1 = caseF(o + d * t1);
      if ((f0 < 0.0) != (f1 < 0.0)) {
        float a = t0, b = t1, fa = f0;
        for (int k = 0; k < 30; ++k) {
          float m = 0.5 * (a + b), fm = caseF(o + d * m);
          if ((fm < 0.0) == (fa < 0.0)) { a = m; fa = fm; } else { b = m; }
        }
        imageStore(uOut, texel(4 * id + found), vec4(o + d * (0.5 * (a + b)), 1.0));
        ++found;
      }
      t0 = t1;
      f0 = f1;
    }
    for (; found < 4; ++found) imageStore(uOut, texel(4 * id + found), vec4(0.0));
  } else {
    vec2 uv = (vec2(float(id % uGrid), float(id / uGrid)) + 0.5) / float(uGrid);
    imageStore(uOut, texel(id), vec4(caseSurface(uv), 1.0));
  }
}
)GLSL";

GLuint compile(const std::string& text) {
  const GLuint sh = glCreateShader(GL_COMPUTE_SHADER);
  const char* s = text.c_str();
  glShaderSource(sh, 1, &s, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  std::string log(4096, '\0');
  GLsizei n = 0;
  glGetShaderInfoLog(sh, static_cast<GLsizei>(log.size()), &n, log.data());
  log.resize(n);
  if (!ok) {
    glDeleteShader(sh);
    throw std::runtime_error("the case's compute shader did not compile:\n" + log);
  }
  const GLuint prog = glCreateProgram();
  glAttachShader(prog, sh);
  glLinkProgram(prog);
  glDeleteShader(sh);
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    glGetProgramInfoLog(prog, static_cast<GLsizei>(log.capacity()), &n, log.data());
    glDeleteProgram(prog);
    throw std::runtime_error("the case's compute shader did not link:\n" + log.substr(0, n));
  }
  return prog;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

GpuCase::GpuCase(const std::string& shader_dir, const CaseSource& src) {
  const std::string body = src.helpers + "\nfloat caseF(vec3 p) { return " + src.f + "; }\n" +
                           "bool caseInside(vec3 p) { return " + src.inside + "; }\n" +
                           "bool caseSkip(vec3 p) { return " + src.skip + "; }\n" +
                           "float caseCheck(vec3 p) { return " + src.check + "; }\n" +
                           "vec3 caseSurface(vec2 uv) { return " + src.surface + "; }\n";
  // Specialized as a scene's shader is: only the library names the case uses.
  std::string root = "#version 450 core\n#define MS_LIBRARY_SUBSET 1\n";
  for (const std::string& name : referenced_library_names(body)) root += "#define USE_" + upper(name) + " 1\n";
  root += "#include \"primitives.glsl\"\n#include \"operators.glsl\"\n#include \"noise.glsl\"\n";
  PreprocessOptions opts;
  opts.include_dirs = {shader_dir};
  text_ = preprocess(root, "library case", shader_dir, opts).text + body + kMain;
  program_ = compile(text_);
}

GpuCase::~GpuCase() { glDeleteProgram(program_); }

std::vector<float> GpuCase::dispatch(int mode, int count, int slots, const std::vector<glm::vec3>& points,
                                     const Box& box, int grid, int steps, int dims) const {
  const int texels = count * slots;
  const int rows = std::max(1, (texels + kWidth - 1) / kWidth);
  GLuint tex[2];
  glGenTextures(2, tex);
  std::vector<float> in(static_cast<size_t>(kWidth) * rows * 4, 0.0f);
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) in[4 * i + k] = points[i][k];
  for (int t = 0; t < 2; ++t) {
    glBindTexture(GL_TEXTURE_2D, tex[t]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, rows, 0, GL_RGBA, GL_FLOAT, t == 0 ? in.data() : nullptr);
  }
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glBindImageTexture(0, tex[1], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  auto set_int = [&](const char* name, int v) { glUniform1i(glGetUniformLocation(program_, name), v); };
  set_int("uPoints", 0);
  set_int("uMode", mode);
  set_int("uCount", count);
  set_int("uGrid", grid);
  set_int("uSteps", steps);
  set_int("uDims", dims);
  glUniform3f(glGetUniformLocation(program_, "uLo"), box.lo.x, box.lo.y, box.lo.z);
  glUniform3f(glGetUniformLocation(program_, "uHi"), box.hi.x, box.hi.y, box.hi.z);
  glDispatchCompute((count + 63) / 64, 1, 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> out(static_cast<size_t>(kWidth) * rows * 4);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
  glDeleteTextures(2, tex);
  out.resize(static_cast<size_t>(texels) * 4);
  return out;
}

std::vector<Sample> GpuCase::eval(const std::vector<glm::vec3>& points) const {
  const std::vector<float> raw = dispatch(0, static_cast<int>(points.size()), 1, points, {}, 1, 1, 3);
  std::vector<Sample> out(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    out[i] = {raw[4 * i], raw[4 * i + 1] > 0.5f, raw[4 * i + 2] > 0.5f, raw[4 * i + 3]};
  return out;
}

std::vector<glm::vec3> GpuCase::zeros(const Box& box, int grid, int steps, int dims) const {
  const int rays = dims == 2 ? 2 * grid : 3 * grid * grid;
  const std::vector<float> raw = dispatch(1, rays, kSlots, {}, box, grid, steps, dims);
  std::vector<glm::vec3> out;
  for (size_t i = 0; i < raw.size() / 4; ++i)
    if (raw[4 * i + 3] > 0.5f) out.emplace_back(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2]);
  return out;
}

std::vector<glm::vec3> GpuCase::surface(int n) const {
  const std::vector<float> raw = dispatch(2, n * n, 1, {}, {}, n, 1, 3);
  std::vector<glm::vec3> out;
  for (size_t i = 0; i < raw.size() / 4; ++i) out.emplace_back(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2]);
  return out;
}

}  // namespace ms::test
