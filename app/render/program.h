// A linked GL program built from preprocessed sources. Compile and link
// errors become one ms::Error naming the original file:line (via
// shader/log_map.h), never a line of the assembled text.
#pragma once
#include <string>
#include <unordered_map>

#include "gl/gl.h"
#include "shader/preprocess.h"

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

 private:
  void link(const ShaderSource& errors_in, const char* what);  // throws the log mapped to errors_in's files
  GLuint id_ = 0;
  mutable std::unordered_map<std::string, GLint> locations_;
};

}  // namespace ms
