// Inside `marchstudio test` (suite/suite_run.cpp): one backend's GL state
// shared by every case of a run, each case's frames, and the image checks
// (suite/suite_images.cpp). Not for use outside suite/suite_*.cpp.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "suite/suite_run.h"
#include "gl/context.h"
#include "pipeline/frame_session.h"
#include "render/still.h"
#include "shader/assemble.h"

namespace ms::suite_detail {

// One backend's frame session and every case's programs in it.
struct Gl {
  explicit Gl(FrameSession& s) : session(s), ctx(s.context()) {}
  FrameSession& session;
  const Context& ctx;
  // Each case's programs for a dispatch, shared through the session's cache.
  std::map<std::pair<const PreparedCase*, Dispatch>, std::unique_ptr<FramePrograms>> jobs;
  // The case's programs with its scene pass drawn by `d` (fragment or compute), made once.
  FramePrograms& job(const PreparedCase& pc, Dispatch d = Dispatch::fragment);
  std::shared_ptr<const Program> program(const ShaderSource& src) {
    return session.cache().get(fullscreen_vertex_source(), src);
  }
};

struct FrameSpec {
  int frame = 0;
  float time = 0.0f, time_delta = 1.0f / 60.0f;
};

// The frames a case renders: its still, or frame f of a range at f / fps.
std::vector<FrameSpec> frames_of(const PreparedCase& pc);
// The still path's input for frame `f` of `posed` (the case's scene at f's time).
StillFrame still_of(const PreparedCase& pc, const Scene& posed, const FrameSpec& f);

// The image checks of every frame, the --update writes and the report's
// images (of the worst frame), into `r`.
void check_images(Gl& gl, const PreparedCase& pc, const RunOptions& opts, CaseResult& r);

}  // namespace ms::suite_detail
