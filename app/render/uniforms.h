// Per-frame uniforms for the two kinds of main program: a scene's (the
// contract in docs/shader-library.md) and a Shadertoy shader's.
#pragma once
#include <array>

#include "render/graph.h"
#include "render/program.h"
#include "scene/scene.h"

namespace ms {

// Camera, sky, lights and materials from the scene; uTime/uFrame as given.
void set_scene_uniforms(const Program& prog, const Scene& scene, int width, int height, float time, int frame);

struct ShadertoyInputs {
  float time = 0.0f;
  float time_delta = 1.0f / 60.0f;
  int frame = 0;
  float mouse[4] = {0, 0, 0, 0};
  float channel_resolution[4][3] = {};  // iChannelResolution: the bound input's size (0 when unbound)
  float channel_time[4] = {};           // iChannelTime: iTime, but 0 for audio that never loaded
};

// iChannel0..3 of a Shadertoy shader: a black 1x1 texture, as an unbound
// Shadertoy input reads. bind() puts it on texture units 0..3.
class BlackChannels {
 public:
  BlackChannels();
  ~BlackChannels();
  BlackChannels(const BlackChannels&) = delete;
  BlackChannels& operator=(const BlackChannels&) = delete;
  void bind() const;

 private:
  GLuint tex_ = 0;
};

// iResolution, iTime, iTimeDelta, iFrameRate, iFrame, iMouse, iDate,
// iChannel*. iDate is 2000-01-01 plus iTime seconds: deterministic, never
// the wall clock. iChannel0..3 are bound to a black 1x1 texture (the caller
// provides it on units 0..3).
void set_shadertoy_uniforms(const Program& prog, int width, int height, const ShadertoyInputs& in);

// glslViewer's uniforms (docs/glslviewer.md), over Shadertoy's: u_resolution
// (pixels), u_time, u_delta, u_frame, u_mouse (iMouse.xy: pixels, origin at
// the lower left), u_date (as iDate), the 2D canvas's identity u_model*
// matrices, and each named sampler on its channel's unit with
// NAMEResolution for a texture.
void set_glslviewer_uniforms(const Program& prog, int width, int height, const ShadertoyInputs& in,
                             const std::array<GraphInput, 4>& inputs);

}  // namespace ms
