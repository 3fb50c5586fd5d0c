#include "render/still.h"

#include <cmath>

#include "core/error.h"

namespace ms {

int still_frame_number(double time, double fps) {
  const double n = std::round(time * fps);
  return n < 0 ? 0 : n > 1e8 ? 100000000 : static_cast<int>(n);
}

void draw_still(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f) {
  draw_still(graph, f, [&](const Program& prog, const UniformFn& set_uniforms) {
    renderer.draw(prog, set_uniforms, post, f.params);
  });
}

void draw_still(PassGraph& graph, const StillFrame& f, const PassGraph::DrawLast& draw_last) {
  if (!graph.stateful()) {
    graph.draw(draw_last, f.in, f.params);
    return;
  }
  const int last = still_frame_number(f.in.time, f.fps);
  graph.reset();
  FrameInputs in = f.in;
  in.time_delta = static_cast<float>(1.0 / f.fps);
  for (int n = 0; n <= last; ++n) {
    in.frame = n;
    in.time = static_cast<float>(static_cast<double>(n) / f.fps);
    if (n < last) graph.step_buffers(in, f.params);  // what later frames read; no image
    else graph.draw(draw_last, in, f.params);
  }
}

long long take_flagged(Image& color) {
  if (color.nchannels() != 4) return 0;
  long long n = 0;
  for (size_t p = 3; p < color.pixels.size(); p += 4)
    if (color.pixels[p] < 0.0f) {
      ++n;
      color.pixels[p] = 1.0f;
    }
  return n;
}

namespace {

Still read_still(const FrameRenderer& renderer, bool aovs) {
  Still out;
  out.color = renderer.read_color();
  out.flagged = take_flagged(out.color);
  if (aovs) out.aovs = renderer.read_aovs();
  return out;
}

}  // namespace

Still render_still(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f) {
  draw_still(renderer, graph, post, f);
  return read_still(renderer, f.params.aovs);
}

Still render_frame(FrameRenderer& renderer, PassGraph& graph, const Program& post, const FrameInputs& in,
                   const FrameParams& p) {
  graph.draw(renderer, post, in, p);
  return read_still(renderer, p.aovs);
}

}  // namespace ms
