#include "render/bloom.h"

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "core/error.h"

namespace ms {

int bloom_size(int n, float scale) { return std::max(1, static_cast<int>(std::lround(n * static_cast<double>(scale)))); }

float bloom_pass_sigma(const Bloom& b) {
  return static_cast<float>(b.radius * static_cast<double>(b.scale) / std::sqrt(static_cast<double>(std::max(b.passes, 1))));
}

int bloom_half_taps(float sigma) {
  if (!(sigma > 0.0f)) return 0;
  return std::clamp(static_cast<int>(std::ceil(3.0 * sigma)), 0, kBloomMaxHalf);
}

BloomStage::BloomStage(const Bloom& settings, std::shared_ptr<const Program> extract,
                       std::shared_ptr<const Program> blur)
    : settings_(settings), extract_(std::move(extract)), blur_(std::move(blur)) {}

BloomStage::~BloomStage() {
  if (fbo_[0]) glDeleteFramebuffers(2, fbo_);
  if (tex_[0]) glDeleteTextures(2, tex_);
}

void BloomStage::resize(int w, int h) {
  if (fbo_[0]) glDeleteFramebuffers(2, fbo_);
  if (tex_[0]) glDeleteTextures(2, tex_);
  w_ = bloom_size(w, settings_.scale);
  h_ = bloom_size(h, settings_.scale);
  glGenTextures(2, tex_);
  glGenFramebuffers(2, fbo_);
  for (int i = 0; i < 2; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex_[i]);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, w_, h_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_[i]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex_[i], 0);
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    glDrawBuffers(1, &buf);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      fail_system("GL: the bloom framebuffer is incomplete");
  }
  src_w_ = w;
  src_h_ = h;
}

void BloomStage::run(GLuint accum, int width, int height, float inv_samples) {
  if (width != src_w_ || height != src_h_ || !tex_[0]) resize(width, height);
  glViewport(0, 0, w_, h_);
  glActiveTexture(GL_TEXTURE0);
  glBindSampler(0, 0);

  // Extract: accumulation buffer -> target 0.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_[0]);
  glUseProgram(extract_->id());
  glBindTexture(GL_TEXTURE_2D, accum);
  extract_->set("uAccum", 0);
  extract_->set("uInvSamples", inv_samples);
  extract_->set("uThreshold", settings_.threshold);
  extract_->set("uSrcSize", glm::ivec2(width, height));
  extract_->set("uDstSize", glm::ivec2(w_, h_));
  glDrawArrays(GL_TRIANGLES, 0, 3);

  // Blur: 0 -> 1 horizontally, 1 -> 0 vertically, per pass; texelFetch
  // ignores the linear filter.
  const float sigma = bloom_pass_sigma(settings_);
  const int half = bloom_half_taps(sigma);
  if (half == 0) return;
  glUseProgram(blur_->id());
  blur_->set("uSrc", 0);
  blur_->set("uSigma", sigma);
  blur_->set("uHalf", half);
  for (int pass = 0; pass < settings_.passes; ++pass) {
    for (int axis = 0; axis < 2; ++axis) {
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_[1 - axis]);
      glBindTexture(GL_TEXTURE_2D, tex_[axis]);
      blur_->set("uDir", glm::ivec2(axis == 0 ? 1 : 0, axis == 0 ? 0 : 1));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
  }
}

}  // namespace ms
