// A linked GL program built from preprocessed sources. Compile and link
// errors become one ms::Error naming the original file:line (via
// shader/log_map.h), never a line of the assembled text.
#pragma once
#include <string>

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
  GLint loc(const std::string& name) const { return glGetUniformLocation(id_, name.c_str()); }

 private:
  void link(const ShaderSource& errors_in, const char* what);  // throws the log mapped to errors_in's files
  GLuint id_ = 0;
};

}  // namespace ms
