// The bloom stage (docs/post.md): between the accumulation and the post pass,
// the parts of the mean linear image above a threshold are box-filtered down
// to a target of scale x the frame's size (bloom_extract.frag), then blurred
// by `passes` separable Gaussian passes (bloom_blur.frag, H then V, ping-pong
// between two targets). post.frag (BLOOM 1) adds the result, upsampled
// bilinearly, times the intensity, before exposure and the tone map.
//
//   BloomStage bloom(scene.bloom, extract_prog, blur_prog);  // context current
//   fp.bloom = &bloom;  renderer.draw(main, set, post_with_bloom, fp);
#pragma once
#include <memory>

#include "gl/gl.h"
#include "render/program.h"
#include "scene/scene.h"

namespace ms {

// The reduced size for a frame of width x height: max(1, round(n x scale)).
int bloom_size(int n, float scale);
// Each pass's sigma in target pixels, radius x scale / sqrt(passes): the
// passes together blur with sigma radius x scale (Gaussians add variances).
float bloom_pass_sigma(const Bloom& b);
// Taps each side of a pass: ceil(3 sigma), at most kBloomMaxHalf.
constexpr int kBloomMaxHalf = 64;
int bloom_half_taps(float sigma);

class BloomStage {
 public:
  BloomStage(const Bloom& settings, std::shared_ptr<const Program> extract, std::shared_ptr<const Program> blur);
  ~BloomStage();
  BloomStage(const BloomStage&) = delete;
  BloomStage& operator=(const BloomStage&) = delete;

  // Runs the passes on `accum` (width x height, sums of 1 / inv_samples
  // samples). Leaves the viewport at the target's size and the framebuffer
  // bound to it; the caller's VAO must be bound. The targets are kept while
  // the frame's size stays the same.
  void run(GLuint accum, int width, int height, float inv_samples);
  GLuint texture() const { return tex_[0]; }  // the result, linear filtering, clamp to edge
  float intensity() const { return settings_.intensity; }

 private:
  void resize(int w, int h);
  Bloom settings_;
  std::shared_ptr<const Program> extract_, blur_;
  GLuint tex_[2] = {0, 0}, fbo_[2] = {0, 0};
  int src_w_ = 0, src_h_ = 0, w_ = 0, h_ = 0;
};

}  // namespace ms
