#include "render/cubemap.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace ms {

namespace {

int levels_for(int size) { return 1 + static_cast<int>(std::floor(std::log2(std::max(size, 1)))); }

}  // namespace

GLuint upload_cube(const CubeFaces& c, const Sampler& sampler) {
  const bool mips = sampler.filter == TexFilter::mipmap;
  const GLenum internal = !c.eight_bit ? GL_RGBA32F : sampler.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, mips ? levels_for(c.size) : 1, internal, c.size, c.size);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  std::vector<float> rows(static_cast<size_t>(c.size) * c.size * 4);
  const size_t row = static_cast<size_t>(c.size) * 4;
  for (int f = 0; f < 6; ++f) {
    const std::vector<float>& px = c.faces[f].pixels;
    for (int y = 0; y < c.size; ++y) {
      const int from = sampler.vflip ? c.size - 1 - y : y;
      std::copy(px.begin() + from * row, px.begin() + (from + 1) * row, rows.begin() + y * row);
    }
    glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, c.size, c.size, GL_RGBA, GL_FLOAT, rows.data());
  }
  if (mips) glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  return tex;
}

CubeBuffer::CubeBuffer(int levels, int size) : size_(size), levels_(levels > 1 ? levels_for(size) : 1) {
  glGenTextures(2, tex_);
  for (GLuint t : tex_) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    glTexStorage2D(GL_TEXTURE_CUBE_MAP, levels_, GL_RGBA16F, size_, size_);  // Shadertoy's Cube A: 4 x half float
  }
  glGenFramebuffers(1, &fbo_);
  clear();
}

CubeBuffer::~CubeBuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(2, tex_);
}

void CubeBuffer::mipmaps(int which) {
  if (levels_ <= 1) return;
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex_[which]);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
}

void CubeBuffer::clear() {
  const float zero[4] = {0, 0, 0, 0};
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  for (int i = 0; i < 2; ++i) {
    for (int f = 0; f < 6; ++f) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, tex_[i], 0);
      glClearBufferfv(GL_COLOR, 0, zero);
    }
    mipmaps(i);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  latest_ = 0;
}

void CubeBuffer::draw(GLuint program, GLuint vao, const std::function<void(int)>& setup, const Deadline* deadline) {
  const int target = 1 - latest_;
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vao);
  for (int f = 0; f < 6; ++f) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, tex_[target], 0);
    if (f == 0 && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      fail_system("GL: the Cube A face's framebuffer is incomplete");
    glViewport(0, 0, size_, size_);
    glUseProgram(program);
    setup(f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (deadline) {
      glFinish();
      if (deadline->expired()) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        deadline->check("the render");
      }
    } else {
      glFlush();
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  mipmaps(target);
  latest_ = target;  // later passes, and the next frame, read this
}

Image CubeBuffer::read() const {
  Image img;
  img.width = size_;
  img.height = 6 * size_;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.resize(static_cast<size_t>(size_) * size_ * 6 * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (int f = 0; f < 6; ++f) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, tex_[latest_], 0);
    glReadPixels(0, 0, size_, size_, GL_RGBA, GL_FLOAT, img.pixels.data() + static_cast<size_t>(f) * size_ * size_ * 4);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return img;
}

void CubeBuffer::write(const Image& img) {
  if (img.width != size_ || img.height != 6 * size_ || img.nchannels() != 4)
    fail_system("internal: a checkpoint that fits no Cube A buffer");
  glBindTexture(GL_TEXTURE_CUBE_MAP, tex_[latest_]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int f = 0; f < 6; ++f)
    glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, size_, size_, GL_RGBA, GL_FLOAT,
                    img.pixels.data() + static_cast<size_t>(f) * size_ * size_ * 4);
  mipmaps(latest_);
}

void CubeBuffer::copy_from(const CubeBuffer& other) {
  if (other.size_ != size_) return;
  for (int i = 0; i < 2; ++i) {
    glCopyImageSubData(other.tex_[i], GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, tex_[i], GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, size_,
                       size_, 6);
    mipmaps(i);
  }
  latest_ = other.latest_;
}

}  // namespace ms
