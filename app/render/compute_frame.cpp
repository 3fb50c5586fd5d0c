#include "render/compute_frame.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/error.h"
#include "render/aov.h"
#include "render/bloom.h"
#include "render/samples.h"
#include "render/tiles.h"

namespace ms {

const char* dispatch_name(Dispatch d) {
  switch (d) {
    case Dispatch::fragment: return "fragment";
    case Dispatch::compute: return "compute";
    case Dispatch::automatic: return "auto";
  }
  return "?";
}

// `n` RGBA32F textures (image units 0..n-1), with a framebuffer on the
// first (the post pass draws into a result target through it).
struct ComputeTargets {
  std::vector<GLuint> tex;
  GLuint fbo = 0;
  int width = 0, height = 0;
  ComputeTargets(int w, int h, int n) : tex(n), width(w), height(h) {
    glGenTextures(n, tex.data());
    for (int i = 0; i < n; ++i) {
      glBindTexture(GL_TEXTURE_2D, tex[i]);
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, w, h);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      fail_system("GL: float framebuffer is incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  ~ComputeTargets() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(static_cast<GLsizei>(tex.size()), tex.data());
  }
  ComputeTargets(const ComputeTargets&) = delete;
  ComputeTargets& operator=(const ComputeTargets&) = delete;
  int count() const { return static_cast<int>(tex.size()); }

  // Texture `i` as RGBA float, top row first.
  std::vector<float> read(int i) const {
    const size_t row = static_cast<size_t>(width) * 4;
    std::vector<float> px(row * height), out(px.size());
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, px.data());
    for (int y = 0; y < height; ++y)
      std::memcpy(out.data() + y * row, px.data() + (height - 1 - y) * row, row * sizeof(float));
    return out;
  }
};

ComputeFrameRenderer::ComputeFrameRenderer(const Context& ctx) : ctx_(ctx) { glGenVertexArrays(1, &vao_); }

ComputeFrameRenderer::~ComputeFrameRenderer() { glDeleteVertexArrays(1, &vao_); }

void ComputeFrameRenderer::draw(const Program& main, const UniformFn& set_uniforms, const Program& post,
                                const FrameParams& p, ComputeGroup group) {
  const int end = p.sample_end < 0 ? std::max(p.spp, 1) : p.sample_end;
  const int begin = std::clamp(p.sample_begin, 0, end);
  if (p.fused_post && (p.spp != 1 || p.aovs || end != 1 || p.bloom))
    fail_system("internal: a fused post pass needs one sample per pixel, no AOVs and no bloom");
  const int images = p.aovs ? 1 + kAovTargets : 1;
  // As FrameRenderer: checked only when targets are (re)made.
  const bool resize = p.width != width_ || p.height != height_ || !result_;
  if (resize || (!p.fused_post && (!accum_ || accum_->count() != images)))
    check_frame_size(ctx_.info(), p.width, p.height, images + 1);
  if (resize) {
    accum_.reset();
    result_ = std::make_unique<ComputeTargets>(p.width, p.height, 1);
    width_ = p.width;
    height_ = p.height;
  }
  if (!p.fused_post && (!accum_ || accum_->count() != images))
    accum_ = std::make_unique<ComputeTargets>(p.width, p.height, images);
  spp_ = std::max(end, 1);
  aovs_ = p.aovs;
  const ComputeTargets& into = p.fused_post ? *result_ : *accum_;

  // As the fragment path: one sample stores, several add (from zero when
  // the frame starts here), sample by sample in the same order.
  const bool add = end - begin > 1 || begin > 0;
  if (add && begin == 0) {
    const float zero[4] = {0, 0, 0, 0};
    for (GLuint t : into.tex) glClearTexImage(t, 0, GL_RGBA, GL_FLOAT, zero);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  for (int i = 0; i < into.count(); ++i)
    glBindImageTexture(static_cast<GLuint>(i), into.tex[i], 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glUseProgram(main.id());
  set_uniforms(main);
  main.set("uPixelOffset", glm::vec2(p.offset_x, p.offset_y));
  if (p.fused_post) main.set("uExposure", p.exposure);
  main.set("uMsAccumulate", add ? 1 : 0);
  std::vector<glm::vec2> samples = p.open_ended ? open_samples(begin, end) : stratified_samples(p.spp);
  if (!p.open_ended) {
    samples.resize(std::min<size_t>(samples.size(), static_cast<size_t>(end)));
    samples.erase(samples.begin(), samples.begin() + std::min<size_t>(samples.size(), static_cast<size_t>(begin)));
  }
  // Tile by tile, every sample of a tile before the next, as FrameRenderer:
  // no dispatch covers more than a tile; a flush between tiles (none after
  // the last), or with a deadline a wait and a check after each dispatch.
  const std::vector<Tile> tiles = split_tiles(p.width, p.height, p.tile_size);
  for (const Tile& t : tiles) {
    main.set("uMsRect", glm::ivec4(t.x, t.y, t.width, t.height));
    const GLuint gx = static_cast<GLuint>((t.width + group.x - 1) / group.x);
    const GLuint gy = static_cast<GLuint>((t.height + group.y - 1) / group.y);
    if (group.stripe > 0) main.set("uMsGroups", glm::ivec2(gx, gy));
    for (const glm::vec2& s : samples) {
      main.set("uJitter", s);
      if (group.stripe > 0) glDispatchCompute(gx * gy, 1, 1);  // remapped in the shader (compute_wrap.h)
      else glDispatchCompute(gx, gy, 1);
      // The next sample reads what this one stored. One sample stores each
      // pixel once and tiles do not overlap: no barrier, which would drain
      // the GPU between tiles (40 a frame at 3840x2160).
      if (add) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      if (p.deadline) {
        glFinish();
        if (p.deadline->expired()) p.deadline->check("the render");
      }
    }
    if (!p.deadline && &t != &tiles.back()) glFlush();
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  for (int i = 0; i < into.count(); ++i)
    glBindImageTexture(static_cast<GLuint>(i), 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);

  // The post pass, FrameRenderer's: a fragment pass over the result.
  if (!p.fused_post) {
    glBindVertexArray(vao_);
    glViewport(0, 0, p.width, p.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glBindSampler(0, 0);
    draw_bloom_and_post(post, accum_->tex[0], result_->fbo, p, spp_);  // render/frame.h, FrameRenderer's own
  }
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    fail_system("GL error " + std::to_string(err) + " while rendering (compute dispatch)");
}

Image ComputeFrameRenderer::read_color() const {
  Image img;
  if (!result_) return img;
  img.width = width_;
  img.height = height_;
  img.channels = {"R", "G", "B", "A"};
  img.pixels = result_->read(0);
  return img;
}

GLuint ComputeFrameRenderer::color_framebuffer() const { return result_ ? result_->fbo : 0; }

Image ComputeFrameRenderer::read_aovs() const {
  if (!aovs_ || !accum_ || accum_->count() != 1 + kAovTargets) return {};
  std::vector<std::vector<float>> targets;
  for (int a = 0; a <= kAovTargets; ++a) targets.push_back(accum_->read(a));
  return aovs_from_targets(targets, width_, height_, spp_);
}

namespace {

// Whether a channel of `pass` is sampled through a mip chain (render/graph.cpp
// binds the keyboard and audio without one).
bool has_mipmapped_input(const PassSource& pass) {
  for (const GraphInput& in : pass.inputs)
    if (in.kind != InputKind::none && in.kind != InputKind::keyboard && in.kind != InputKind::music &&
        in.kind != InputKind::musicstream &&
        in.sampler.filter == TexFilter::mipmap)
      return true;
  return false;
}

}  // namespace

ShaderSource compute_source(const PassSource& pass, ComputeGroup group) {
  return wrap_compute(pass.source, group, has_mipmapped_input(pass));
}

ComputeStill::ComputeStill(const Context& ctx, const PassGraph& graph, ComputeGroup group)
    : main_(Program::Compute{}, compute_source(graph.pass(graph.size() - 1), group)), renderer_(ctx), group_(group) {}

Still ComputeStill::render(PassGraph& graph, const Program& post, const StillFrame& f) {
  const FrameParams& p = f.params;
  draw_still(graph, f, [&](const Program&, const UniformFn& set_uniforms) {
    renderer_.draw(main_, set_uniforms, post, p, group_);
  });
  Still out;
  out.color = renderer_.read_color();
  out.flagged = take_flagged(out.color);
  if (p.aovs) out.aovs = renderer_.read_aovs();
  return out;
}

Still render_still_compute(const Context& ctx, PassGraph& graph, const Program& post, const StillFrame& f,
                           ComputeGroup group) {
  return ComputeStill(ctx, graph, group).render(graph, post, f);
}

Still render_still_compute(const Context& ctx, const PassSource& pass, const Program& post, const StillFrame& f,
                           ComputeGroup group) {
  PassGraph graph({pass});
  return render_still_compute(ctx, graph, post, f, group);
}

}  // namespace ms
