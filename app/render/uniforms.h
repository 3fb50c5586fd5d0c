// Per-frame uniforms for the two kinds of main program: a scene's (the
// contract in docs/shader-library.md) and a Shadertoy shader's.
#pragma once
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

}  // namespace ms
