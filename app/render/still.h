// One still image of a loaded input: what `render` draws and `test` checks,
// through its pass graph (render/graph.h). A stateless graph (a scene, a
// single-pass shader) draws once at the still's time; a graph with buffers
// replays frames 0..N, N = round(time x fps), each at time f / fps with
// iTimeDelta 1 / fps, the buffers only until the last, which is drawn
// whole: the still is frame N of the sequence at that fps.
//
//   StillFrame f;  f.in.scene = &posed;  f.in.time = t;  f.params = fp;
//   Still s = render_still(renderer, graph, post, f);
#pragma once
#include "io/image.h"
#include "render/frame.h"
#include "render/graph.h"

namespace ms {

struct StillFrame {
  FrameInputs in;      // scene (posed at in.time), time, frame, mouse
  FrameParams params;  // size, samples, post
  double fps = 60.0;   // a stateful graph's frame rate
};

struct Still {
  Image color;  // R, G, B, A, top row first; alpha 1
  Image aovs;   // FrameRenderer::read_aovs() when params.aovs, else empty
  // Pixels a Shadertoy Image pass wrote a NaN or Inf into, each channel
  // already converted as a float-to-unorm write does (importers/shadertoy.h);
  // the NaN/Inf guard adds them to what it counts.
  long long flagged = 0;
};

// The frame this still is of a stateful graph: round(time x fps).
int still_frame_number(double time, double fps);

// Draws the still; the result stays in `renderer` (read_color, read_aovs).
// Timing loops call this: nothing is read back.
void draw_still(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f);
// The same with the last pass drawn by `draw_last` (PassGraph::draw's
// second form): the compute dispatch's still (render/compute_frame.h).
void draw_still(PassGraph& graph, const StillFrame& f, const PassGraph::DrawLast& draw_last);

// draw_still(), then the colour (and the AOVs when params.aovs) read back.
Still render_still(FrameRenderer& renderer, PassGraph& graph, const Program& post, const StillFrame& f);

// One frame of a graph that goes on from where it stands (a sequence's next
// frame): graph.draw(), then the colour (and AOVs) read back.
Still render_frame(FrameRenderer& renderer, PassGraph& graph, const Program& post, const FrameInputs& in,
                   const FrameParams& p);

// Counts the pixels whose alpha marks a non-finite sample and sets their
// alpha to 1 (what render_still does with its colour); the count.
long long take_flagged(Image& color);

}  // namespace ms
