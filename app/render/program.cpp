#include "render/program.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "preprocess/log_map.h"

namespace ms {
namespace {

// Info log of a shader or program: the two differ only in their getters.
template <class GetIv, class GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint len = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(len > 0 ? len : 0, '\0');
  GLsizei written = 0;
  if (len > 0) get_log(object, len, &written, log.data());
  // INFO_LOG_LENGTH counts the terminating NUL: kept, it read as one more
  // diagnostic ("+1 more" for a single error).
  log.resize(static_cast<size_t>(std::clamp<GLsizei>(written, 0, len)));
  return log;
}

std::string shader_log(GLuint shader) { return info_log(shader, glGetShaderiv, glGetShaderInfoLog); }
std::string program_log(GLuint program) { return info_log(program, glGetProgramiv, glGetProgramInfoLog); }

// The first error-level diagnostic as the one-line Error; the count of the
// rest goes into the hint so nothing is silently dropped.
[[noreturn]] void fail_with_log(const std::string& stage, const std::string& log, const ShaderSource& src) {
  std::vector<ShaderDiagnostic> diags = parse_info_log(log, src);
  suggest_names(diags, src.text);
  const ShaderDiagnostic* first = nullptr;
  int errors = 0;
  for (const auto& d : diags) {
    if (d.severity == "warning") continue;
    if (!first) first = &d;
    ++errors;
  }
  if (!first && !diags.empty()) first = &diags.front();
  if (!first) fail_input(stage + " failed with an empty log", src.files.empty() ? "" : src.files[0]);
  std::string hint = first->suggestion;
  if (errors > 1) hint += (hint.empty() ? "+" : "; +") + std::to_string(errors - 1) + " more; " + std::string(kVerboseHint);
  // The whole log, mapped, for -v: what "+N more" stands for.
  throw Error(ErrorInfo{Exit::bad_input, first->file, first->line, {}, stage + " error: " + first->message, hint,
                        format_diagnostics(diags)});
}

GLuint compile(GLenum type, const std::string& text, const ShaderSource& src, const char* stage) {
  GLuint shader = glCreateShader(type);
  const char* p = text.c_str();
  glShaderSource(shader, 1, &p, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    fail_with_log(stage, log, src);
  }
  return shader;
}

}  // namespace

Program::Program(const std::string& vertex_source, const ShaderSource& fragment) {
  ShaderSource vertex;
  vertex.text = vertex_source;
  vertex.files = {"<fullscreen vertex shader>"};
  GLuint vs = compile(GL_VERTEX_SHADER, vertex_source, vertex, "vertex shader compile");
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment.text, fragment, "shader compile");
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glDeleteShader(vs);  // flagged: freed with the program
  glDeleteShader(fs);
  link(fragment, "shader link");
}

Program::Program(Compute, const ShaderSource& compute) {
  GLuint cs = compile(GL_COMPUTE_SHADER, compute.text, compute, "compute shader compile");
  id_ = glCreateProgram();
  glAttachShader(id_, cs);
  glDeleteShader(cs);
  link(compute, "compute shader link");
}

void Program::link(const ShaderSource& errors_in, const char* what) {
  glLinkProgram(id_);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = program_log(id_);
    glDeleteProgram(id_);
    id_ = 0;
    fail_with_log(what, log, errors_in);
  }
}

namespace {
// A viewer may compile and draw on a second thread (shared context).
std::atomic<long long> g_gl_lookups{0}, g_gl_sets{0};
}  // namespace

Program::Uniform& Program::uniform(const std::string& name) const {
  if (const auto it = uniforms_.find(name); it != uniforms_.end()) return it->second;
  ++g_gl_lookups;
  Uniform u;
  u.loc = glGetUniformLocation(id_, name.c_str());
  return uniforms_.emplace(name, std::move(u)).first->second;
}

GLint Program::loc(const std::string& name) const { return uniform(name).loc; }

bool Program::changed(Uniform& u, const void* bytes, size_t size) const {
  if (u.loc < 0) return false;
  if (u.bits.size() == size && std::memcmp(u.bits.data(), bytes, size) == 0) return false;
  u.bits.assign(static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
  ++g_gl_sets;
  return true;
}

void Program::set(const std::string& name, int v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform1i(id_, u.loc, v);
}
void Program::set(const std::string& name, float v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform1f(id_, u.loc, v);
}
void Program::set(const std::string& name, const glm::ivec2& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform2iv(id_, u.loc, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::ivec4& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform4iv(id_, u.loc, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec2& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform2fv(id_, u.loc, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec3& v) const { set(name, &v, 1); }
void Program::set(const std::string& name, const glm::vec4& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v)) glProgramUniform4fv(id_, u.loc, 1, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::mat3& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v))
    glProgramUniformMatrix3fv(id_, u.loc, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::mat4& v) const {
  if (Uniform& u = uniform(name); changed(u, &v, sizeof v))
    glProgramUniformMatrix4fv(id_, u.loc, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const std::string& name, const glm::vec3* v, int count) const {
  if (Uniform& u = uniform(name); count > 0 && changed(u, v, sizeof(glm::vec3) * static_cast<size_t>(count)))
    glProgramUniform3fv(id_, u.loc, count, glm::value_ptr(v[0]));
}

long long Program::gl_lookups() { return g_gl_lookups.load(); }
long long Program::gl_uniform_sets() { return g_gl_sets.load(); }

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace ms
