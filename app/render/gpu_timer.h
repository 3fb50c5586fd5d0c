// GPU time of a span of GL commands through GL_TIME_ELAPSED queries. A small
// ring of queries so reading a result never stalls the frame that follows
// (the viewer); bench reads synchronously after a finish.
#pragma once
#include <array>
#include <optional>

#include "gl/gl.h"

namespace ms {

class GpuTimer {
 public:
  GpuTimer() { glGenQueries(static_cast<GLsizei>(queries_.size()), queries_.data()); }
  ~GpuTimer() { glDeleteQueries(static_cast<GLsizei>(queries_.size()), queries_.data()); }
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin() { glBeginQuery(GL_TIME_ELAPSED, queries_[next_]); }
  void end() {
    glEndQuery(GL_TIME_ELAPSED);
    pending_[next_] = true;
    last_ = next_;
    next_ = (next_ + 1) % queries_.size();
  }

  // Milliseconds of the most recent span whose result is ready, without
  // waiting; empty when none is.
  std::optional<double> poll_ms() {
    std::optional<double> out;
    for (size_t k = 0; k < queries_.size(); ++k) {
      const size_t i = (next_ + k) % queries_.size();  // oldest first
      if (!pending_[i]) continue;
      GLint ready = 0;
      glGetQueryObjectiv(queries_[i], GL_QUERY_RESULT_AVAILABLE, &ready);
      if (!ready) break;
      GLuint64 ns = 0;
      glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &ns);
      pending_[i] = false;
      out = static_cast<double>(ns) * 1e-6;
    }
    return out;
  }

  // Milliseconds of the last span, waiting for it.
  double wait_ms() {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[last_], GL_QUERY_RESULT, &ns);
    pending_[last_] = false;
    return static_cast<double>(ns) * 1e-6;
  }

 private:
  std::array<GLuint, 4> queries_{};
  std::array<bool, 4> pending_{};
  size_t next_ = 0, last_ = 0;
};

}  // namespace ms
