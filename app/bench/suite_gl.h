// Inside `marchstudio test` (bench/suite_run.cpp): one backend's GL state
// shared by every case of a run, each case's frames, and the image checks
// (bench/suite_images.cpp). Not for use outside bench/suite_*.cpp.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/suite_run.h"
#include "gl/context.h"
#include "render/bloom.h"
#include "render/program_cache.h"
#include "render/still.h"
#include "shader/assemble.h"

namespace ms::suite_detail {

// One backend's context and everything that shares it.
struct Gl {
  explicit Gl(const Context& c) : ctx(c), cache(64), renderer(c) {}
  const Context& ctx;
  ProgramCache cache;
  FrameRenderer renderer;
  std::map<const PreparedCase*, std::unique_ptr<PassGraph>> graphs;  // programs shared through `cache`
  const std::string vs = fullscreen_vertex_source();
  std::shared_ptr<const Program> program(const ShaderSource& src) { return cache.get(vs, src); }
  PassGraph& graph(const PreparedCase& pc) {
    std::unique_ptr<PassGraph>& g = graphs[&pc];
    if (!g) g = std::make_unique<PassGraph>(pc.passes, &cache);
    return *g;
  }
  std::map<const PreparedCase*, std::unique_ptr<BloomStage>> blooms;
  // The case's bloom stage, as render builds it; nullptr without bloom.
  BloomStage* bloom(const PreparedCase& pc) {
    if (pc.bloom.size() != 2) return nullptr;
    std::unique_ptr<BloomStage>& b = blooms[&pc];
    if (!b) b = std::make_unique<BloomStage>(pc.scene.bloom, program(pc.bloom[0]), program(pc.bloom[1]));
    return b.get();
  }
};

struct FrameSpec {
  int frame = 0;
  float time = 0.0f, time_delta = 1.0f / 60.0f;
};

// The frames a case renders: its still, or frame f of a range at f / fps.
std::vector<FrameSpec> frames_of(const PreparedCase& pc);
// The still path's input for frame `f` of `posed` (the case's scene at f's time).
StillFrame still_of(Gl& gl, const PreparedCase& pc, const Scene& posed, const FrameSpec& f);

// The image checks of every frame, the --update writes and the report's
// images (of the worst frame), into `r`.
void check_images(Gl& gl, const PreparedCase& pc, const RunOptions& opts, CaseResult& r);

}  // namespace ms::suite_detail
