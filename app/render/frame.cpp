#include "render/frame.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/aov.h"
#include "render/bloom.h"
#include "render/samples.h"

namespace ms {
namespace {

// The AOV attachments after the colour one (outGeom, outMisc, outCost).

// Images are stored top row first; GL's first row is the bottom one.
void flip_rows(Image& img) {
  const size_t row = static_cast<size_t>(img.width) * img.nchannels();
  std::vector<float> tmp(row);
  for (int y = 0; y < img.height / 2; ++y) {
    float* a = img.pixels.data() + y * row;
    float* b = img.pixels.data() + (img.height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row * sizeof(float));
    std::memcpy(a, b, row * sizeof(float));
    std::memcpy(b, tmp.data(), row * sizeof(float));
  }
}

}  // namespace

// `n` RGBA32F textures as colour attachments 0..n-1 of one framebuffer
// (n > 1: the AOV targets, written in one pass through glDrawBuffers).
struct RenderTarget {
  std::vector<GLuint> tex;
  GLuint fbo = 0;
  RenderTarget(int w, int h, int n = 1) : tex(n) {
    glGenTextures(n, tex.data());
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> bufs;
    for (int i = 0; i < n; ++i) {
      glBindTexture(GL_TEXTURE_2D, tex[i]);
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, w, h);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, tex[i], 0);
      bufs.push_back(GL_COLOR_ATTACHMENT0 + i);
    }
    glDrawBuffers(n, bufs.data());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      fail_system("GL: float framebuffer is incomplete");
  }
  ~RenderTarget() {
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(static_cast<GLsizei>(tex.size()), tex.data());
  }
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;
  int count() const { return static_cast<int>(tex.size()); }
};

// Reads colour attachment `i` of `fbo` as RGBA float, top row first.
static std::vector<float> read_attachment(GLuint fbo, int i, int w, int h) {
  Image img;
  img.width = w;
  img.height = h;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.resize(static_cast<size_t>(w) * h * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + i);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, img.pixels.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  flip_rows(img);
  return std::move(img.pixels);
}

int gl_max_width(const GlInfo& info) {
  return info.max_texture_size > 0 ? std::min(info.max_viewport[0], info.max_texture_size) : info.max_viewport[0];
}

int gl_max_height(const GlInfo& info) {
  return info.max_texture_size > 0 ? std::min(info.max_viewport[1], info.max_texture_size) : info.max_viewport[1];
}

void check_frame_size(const GlInfo& info, int width, int height, int targets) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) fail_input("image size " + size + " must be at least 1x1", {}, 0, "--size");
  const int max_w = gl_max_width(info), max_h = gl_max_height(info);
  if (width > max_w || height > max_h)
    fail_input("image size " + size + " exceeds this GL's limit of " + std::to_string(max_w) + "x" +
                   std::to_string(max_h),
               {}, 0, "--size", "GL_MAX_VIEWPORT_DIMS / GL_MAX_TEXTURE_SIZE of " + info.renderer);
  check_frame_memory(frame_memory(width, height, targets, targets > 2), width, height);
}

FrameRenderer::FrameRenderer(const Context& ctx) : ctx_(ctx) { glGenVertexArrays(1, &vao_); }

FrameRenderer::~FrameRenderer() { glDeleteVertexArrays(1, &vao_); }  // targets free themselves

void draw_bloom_and_post(const Program& post, GLuint accum, GLuint result_fbo, const FrameParams& p, int samples) {
  if (p.bloom) {  // render/bloom.h: its passes at their own size, then the post pass adds the result
    p.bloom->run(accum, p.width, p.height, 1.0f / static_cast<float>(samples));
    glViewport(0, 0, p.width, p.height);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, result_fbo);
  glUseProgram(post.id());
  if (p.bloom) {
    glActiveTexture(GL_TEXTURE1);
    glBindSampler(1, 0);
    glBindTexture(GL_TEXTURE_2D, p.bloom->texture());
    post.set("uBloom", 1);
    post.set("uBloomIntensity", p.bloom->intensity());
  } else if (post.loc("uBloom") >= 0) {
    fail_system("internal: a post pass with bloom drawn without its bloom stage");
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, accum);
  post.set("uAccum", 0);
  post.set("uInvSamples", 1.0f / static_cast<float>(samples));
  post.set("uExposure", p.exposure);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FrameRenderer::draw(const Program& main, const UniformFn& set_uniforms, const Program& post,
                         const FrameParams& p) {
  const int end = p.sample_end < 0 ? std::max(p.spp, 1) : p.sample_end;
  const int begin = std::clamp(p.sample_begin, 0, end);
  if (p.fused_post && (p.spp != 1 || p.aovs || end != 1 || p.bloom))
    fail_system("internal: a fused post pass needs one sample per pixel, no AOVs and no bloom");
  const int attachments = p.aovs ? 1 + kAovTargets : 1;
  // Checked only when targets are (re)made: an unchanged frame passed it
  // before, and it builds strings and asks the OS for its memory each time.
  const bool resize = p.width != width_ || p.height != height_ || !result_;
  if (resize || (!p.fused_post && (!accum_ || accum_->count() != attachments)))
    check_frame_size(ctx_.info(), p.width, p.height, attachments + 1);
  if (resize) {
    accum_.reset();
    result_ = std::make_unique<RenderTarget>(p.width, p.height);
    width_ = p.width;
    height_ = p.height;
  }
  if (!p.fused_post && (!accum_ || accum_->count() != attachments))
    accum_ = std::make_unique<RenderTarget>(p.width, p.height, attachments);
  spp_ = std::max(end, 1);
  aovs_ = p.aovs;
  glBindVertexArray(vao_);
  glViewport(0, 0, p.width, p.height);
  glDisable(GL_DEPTH_TEST);

  // Samples add up in the float buffers (blending applies to every draw
  // buffer, AOVs included); post divides the colour by the count.
  // One sample writes every pixel exactly once (the tiles do not overlap):
  // no clear and no blending, which on llvmpipe read back the whole float
  // buffer (about 15% of a fast frame at 1280x720).
  glBindFramebuffer(GL_FRAMEBUFFER, p.fused_post ? result_->fbo : accum_->fbo);
  if (end - begin > 1 || begin > 0) {
    if (begin == 0) {
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  glUseProgram(main.id());
  set_uniforms(main);
  // Integers, so floor(gl_FragCoord.xy) + uPixelOffset is exactly the pixel
  // an untiled draw sees (floats hold every integer below 2^24).
  main.set("uPixelOffset", glm::vec2(p.offset_x, p.offset_y));
  if (p.fused_post) main.set("uExposure", p.exposure);
  // Tile by tile (scissor; the viewport stays whole, so gl_FragCoord and the
  // image are unchanged), every sample of a tile before the next: no draw
  // covers more than a tile. A flush between tiles submits each on its own
  // (a GPU watchdog times single submissions); none after the last, which
  // whatever ends the frame submits (the readback, glFinish, the swap), so a
  // frame of one tile makes no flush. With a deadline each draw is waited
  // for and the deadline checked, the finest point llvmpipe can stop at.
  std::vector<glm::vec2> samples = p.open_ended ? open_samples(begin, end) : stratified_samples(p.spp);
  if (!p.open_ended) {
    samples.resize(std::min<size_t>(samples.size(), static_cast<size_t>(end)));
    samples.erase(samples.begin(), samples.begin() + std::min<size_t>(samples.size(), static_cast<size_t>(begin)));
  }
  glEnable(GL_SCISSOR_TEST);
  const std::vector<Tile> tiles = split_tiles(p.width, p.height, p.tile_size);
  for (const Tile& t : tiles) {
    glScissor(t.x, t.y, t.width, t.height);
    for (const glm::vec2& s : samples) {
      main.set("uJitter", s);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      if (p.deadline) {
        glFinish();
        if (p.deadline->expired()) {
          glDisable(GL_SCISSOR_TEST);
          glDisable(GL_BLEND);
          glBindFramebuffer(GL_FRAMEBUFFER, 0);
          p.deadline->check("the render");
        }
      }
    }
    if (!p.deadline && &t != &tiles.back()) glFlush();
  }
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);

  // The post pass (not for a fused main pass, which wrote the result).
  if (!p.fused_post) {
    glBindSampler(0, 0);  // a channel's sampler object must not filter the accumulation buffer
    draw_bloom_and_post(post, accum_->tex[0], result_->fbo, p, spp_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    fail_system("GL error " + std::to_string(err) + " while rendering");
}

Image FrameRenderer::read_color() const {
  Image img;
  if (!result_) return img;
  img.width = width_;
  img.height = height_;
  img.channels = {"R", "G", "B", "A"};
  img.pixels = read_attachment(result_->fbo, 0, width_, height_);
  return img;
}

Image FrameRenderer::read_aovs() const {
  if (!aovs_ || !accum_ || accum_->count() != 1 + kAovTargets) return {};
  std::vector<std::vector<float>> targets;
  for (int a = 0; a <= kAovTargets; ++a) targets.push_back(read_attachment(accum_->fbo, a, width_, height_));
  return aovs_from_targets(targets, width_, height_, spp_);
}

GLuint FrameRenderer::color_texture() const { return result_ ? result_->tex[0] : 0; }
GLuint FrameRenderer::color_framebuffer() const { return result_ ? result_->fbo : 0; }

Image FrameRenderer::render(const Program& main, const UniformFn& set_uniforms, const Program& post,
                            const FrameParams& p) {
  draw(main, set_uniforms, post, p);
  return read_color();
}

}  // namespace ms
