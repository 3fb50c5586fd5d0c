// One frame: N jittered samples of a main program accumulated additively into
// a float buffer, then a post program (average, exposure, tone map, encode),
// read back top row first; or, for one sample of a main program that encodes
// its own output (FrameParams::fused_post), that one pass straight into the
// result. Shared by scenes and Shadertoy shaders.
#pragma once
#include <functional>
#include <memory>

#include "core/deadline.h"
#include "gl/context.h"
#include "io/image.h"
#include "render/program.h"
#include "render/tiles.h"

namespace ms {

struct FrameParams {
  int width = 0;
  int height = 0;
  int spp = 1;
  float exposure = 1.0f;
  // Also accumulate the AOV targets (locations 1..3): the main program must be
  // assembled with AOV_OUTPUTS 1 (render/aov.h). read_aovs() reads them.
  bool aovs = false;
  // The main program writes the output pixels itself: it was assembled with
  // fused_post_defines() (shader/assemble.h). Needs spp 1 and no AOVs; the
  // frame then has no accumulation buffer and no post pass.
  bool fused_post = false;
  // Largest square one draw covers (render/tiles.h); <= 0: one draw per sample.
  int tile_size = kTileSize;
  // One tile of a larger image (render/tiled_still.h): width x height is
  // then the tile's framebuffer, image_width x image_height the image the
  // shader sees (uResolution / iResolution) and offset_x, offset_y the
  // tile's lower-left pixel in it (uPixelOffset, GL's rows: bottom first).
  // 0: the frame is the whole image.
  int image_width = 0, image_height = 0;
  int offset_x = 0, offset_y = 0;
  int resolution_width() const { return image_width > 0 ? image_width : width; }
  int resolution_height() const { return image_height > 0 ? image_height : height; }
  // Progressive accumulation (the viewer): draw only samples
  // [sample_begin, sample_end) of the frame's sequence, adding them to what
  // the draws before left in the accumulation buffer (sample_begin 0
  // starts afresh); post then averages over sample_end samples. After draws
  // of 0..1, 1..2, ..., N-1..N the frame equals one draw of all N (the same
  // samples, added in the same order). The sequence is stratified_samples(spp),
  // or with open_ended open_samples() (no limit). -1: all spp samples.
  int sample_begin = 0;
  int sample_end = -1;
  bool open_ended = false;
  // When set, every draw is waited for (glFinish) and the deadline checked
  // after it: draw() throws the --timeout error (Exit::system) once it passed.
  const Deadline* deadline = nullptr;
  // The bloom stage (render/bloom.h), run between the accumulation and the
  // post program, which must then be assemble_post(..., bloom = true); not
  // with fused_post. nullptr: no bloom.
  class BloomStage* bloom = nullptr;
};

// Sets the main program's per-frame uniforms (it is bound when called).
using UniformFn = std::function<void(const Program&)>;

// Throws bad_input (key "--size") when width/height is not in 1..the GL
// limits, or the frame would exceed the memory budget (render/tiles.h).
// `targets`: how many RGBA32F buffers the frame needs (2 plain, 5 with AOVs).
void check_frame_size(const GlInfo& info, int width, int height, int targets = 2);
// The largest framebuffer this GL makes: GL_MAX_VIEWPORT_DIMS within
// GL_MAX_TEXTURE_SIZE. Past it a still is drawn in tiles (render/tiled_still.h).
int gl_max_width(const GlInfo& info);
int gl_max_height(const GlInfo& info);

struct RenderTarget;  // an RGBA32F texture with its framebuffer (frame.cpp)

// The end of every frame, fragment or compute: p.bloom's passes on the
// accumulated `accum` (when set), then `post` into `result_fbo`, averaging
// over `samples`. Leaves the default framebuffer bound.
void draw_bloom_and_post(const Program& post, GLuint accum, GLuint result_fbo, const FrameParams& p, int samples);

class FrameRenderer {
 public:
  explicit FrameRenderer(const Context& ctx);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Accumulate p.spp samples of `main` tile by tile, then run `post` into
  // the result target (with p.fused_post: `main` alone, into the result). Targets are kept while the size stays the same (the viewer draws
  // every frame).
  void draw(const Program& main, const UniformFn& set_uniforms, const Program& post, const FrameParams& p);
  // The post output of the last draw(): channels R,G,B,A, top row first.
  Image read_color() const;
  // The AOVs of the last draw() with FrameParams::aovs, averaged over its
  // samples: channels kAovChannels (render/aov.h), top row first. Empty
  // Image when the last draw had no AOVs.
  Image read_aovs() const;
  // The post output as a texture and framebuffer (the viewer blits it).
  GLuint color_texture() const;
  GLuint color_framebuffer() const;

  // draw() then read_color().
  Image render(const Program& main, const UniformFn& set_uniforms, const Program& post, const FrameParams& p);

 private:
  const Context& ctx_;
  GLuint vao_ = 0;
  int width_ = 0, height_ = 0, spp_ = 1;
  bool aovs_ = false;  // the last draw() accumulated AOVs
  std::unique_ptr<RenderTarget> accum_, result_;
};

}  // namespace ms
