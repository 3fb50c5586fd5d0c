// A linked GL program built from preprocessed sources. Compile and link
// errors become one ms::Error naming the original file:line (via
// preprocess/log_map.h), never a line of the assembled text.
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/fwd.hpp>

#include "gl/gl.h"
#include "preprocess/preprocess.h"

namespace ms {

class Program {
 public:
  Program(const std::string& vertex_source, const ShaderSource& fragment);
  // A compute program (GL 4.3+) of one compute shader: render/compute_frame.h.
  struct Compute {};
  Program(Compute, const ShaderSource& compute);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return id_; }
  // -1 when the uniform is absent or compiled out; glUniform* ignores -1.
  // Asked of the GL once per name, then kept: every frame sets the same
  // uniforms, and a lookup is a string hash and parse inside the driver.
  GLint loc(const std::string& name) const;
  // glGetUniformLocation calls made by every Program so far (the cost test
  // of bench's per-frame host work: none after the first frame).
  static long long gl_lookups();

  // Uniform `name` of this program (glProgramUniform*: bound or not), unless
  // it is absent or already holds exactly these bits. A program keeps its
  // uniforms, and a frame sets the same values as the last one but for a
  // few (time, frame, jitter). Every write to a Program's uniforms must come
  // through here, or the kept values go stale.
  void set(const std::string& name, int v) const;
  void set(const std::string& name, float v) const;
  void set(const std::string& name, const glm::ivec2& v) const;
  void set(const std::string& name, const glm::ivec4& v) const;
  void set(const std::string& name, const glm::vec2& v) const;
  void set(const std::string& name, const glm::vec3& v) const;
  void set(const std::string& name, const glm::vec4& v) const;
  void set(const std::string& name, const glm::mat3& v) const;
  void set(const std::string& name, const glm::mat4& v) const;
  void set(const std::string& name, const glm::vec3* v, int count) const;  // an array from its [0]
  // glProgramUniform* calls made by every Program so far (bench's
  // /uniform_sets: in a still scene's later frames, only what changed).
  static long long gl_uniform_sets();

 private:
  struct Uniform {
    GLint loc = -1;
    std::vector<unsigned char> bits;  // the value last set; empty before the first
  };
  Uniform& uniform(const std::string& name) const;  // looked up once, then kept
  // True (and kept) when `bytes` differ from what u holds and u exists.
  bool changed(Uniform& u, const void* bytes, size_t size) const;
  void link(const ShaderSource& errors_in, const char* what);  // throws the log mapped to errors_in's files
  GLuint id_ = 0;
  mutable std::unordered_map<std::string, Uniform> uniforms_;
};

}  // namespace ms
