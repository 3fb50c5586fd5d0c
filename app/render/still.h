// One still image of a loaded input: what `render` draws and `test` checks.
// A scene's main pass gets the scene uniforms, a Shadertoy shader's its
// iTime/iFrame/iChannel uniforms; both go through one FrameRenderer::draw.
// When inputs gain passes (a pass graph), this is where they are run, so
// every caller gets them at once.
//
//   StillFrame f;  f.scene = &posed;  f.time = t;  f.params = fp;
//   Still s = render_still(renderer, main_prog, post_prog, f);
#pragma once
#include "io/image.h"
#include "render/frame.h"
#include "scene/scene.h"

namespace ms {

struct StillFrame {
  const Scene* scene = nullptr;  // posed at `time` (scene/animation.h animated()); Shadertoy when shadertoy_file is set
  float time = 0.0f;             // uTime / iTime, seconds
  float time_delta = 1.0f / 60.0f;  // iTimeDelta of a Shadertoy shader
  int frame = 0;                 // uFrame / iFrame
  FrameParams params;
};

struct Still {
  Image color;  // R, G, B, A, top row first
  Image aovs;   // FrameRenderer::read_aovs() when params.aovs, else empty
};

// Draws the frame; the result stays in `renderer` (read_color, read_aovs).
// Timing loops call this: nothing is read back.
void draw_still(FrameRenderer& renderer, const Program& main, const Program& post, const StillFrame& f);

// draw_still(), then the colour (and the AOVs when params.aovs) read back.
Still render_still(FrameRenderer& renderer, const Program& main, const Program& post, const StillFrame& f);

}  // namespace ms
