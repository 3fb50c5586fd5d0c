// PassGraph's buffer state (render/graph.h): the buffers' textures made
// for a size, cleared, carried over a reload, and read and written for a
// sequence's checkpoints.
#include "core/error.h"
#include "render/graph.h"
#include "render/graph_state.h"

namespace ms {

void PassGraph::ensure_buffers(int w, int h) {
  Gpu& g = *gpu_;
  if (g.width == w && g.height == h) return;
  for (int b = 0; b < 4; ++b) {
    Buffer& buf = g.buffers[b];
    glDeleteFramebuffers(2, buf.fbo);
    glDeleteTextures(2, buf.tex);
    buf = Buffer{};
    if (!g.used[b]) continue;
    for (const PassSource& p : passes_)
      for (const GraphInput& in : p.inputs)
        if (in.kind == InputKind::buffer && in.buffer == b && in.sampler.filter == TexFilter::mipmap)
          buf.levels = mip_levels(w, h);
    glGenTextures(2, buf.tex);
    glGenFramebuffers(2, buf.fbo);
    for (int i = 0; i < 2; ++i) {
      glBindTexture(GL_TEXTURE_2D, buf.tex[i]);
      glTexStorage2D(GL_TEXTURE_2D, buf.levels, GL_RGBA32F, w, h);
      glBindFramebuffer(GL_FRAMEBUFFER, buf.fbo[i]);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, buf.tex[i], 0);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail_system("GL: a float buffer's framebuffer is incomplete");
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  g.width = w;
  g.height = h;
  clear_buffers();  // not Cube A: its faces do not follow the image's size (as Shadertoy)
}

void PassGraph::reset() {
  clear_buffers();
  if (gpu_->cube_a) gpu_->cube_a->clear();
}

void PassGraph::clear_buffers() {
  Gpu& g = *gpu_;
  const float zero[4] = {0, 0, 0, 0};
  for (int b = 0; b < 4; ++b) {
    if (!g.used[b] || !g.buffers[b].fbo[0]) continue;
    for (int i = 0; i < 2; ++i) {
      glBindFramebuffer(GL_FRAMEBUFFER, g.buffers[b].fbo[i]);
      glClearBufferfv(GL_COLOR, 0, zero);
      if (g.buffers[b].levels > 1) {
        glBindTexture(GL_TEXTURE_2D, g.buffers[b].tex[i]);
        glGenerateMipmap(GL_TEXTURE_2D);
      }
    }
    g.buffers[b].latest = 0;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PassGraph::adopt_buffers(const PassGraph& old) {
  const Gpu& o = *old.gpu_;
  if (o.width == 0 || o.height == 0) return;
  ensure_buffers(o.width, o.height);
  Gpu& g = *gpu_;
  for (int b = 0; b < 4; ++b) {
    if (!g.used[b] || !o.used[b] || !o.buffers[b].tex[0]) continue;
    const Buffer& from = o.buffers[b];
    Buffer& to = g.buffers[b];
    for (int i = 0; i < 2; ++i)  // both: a pass may read the previous frame
      glCopyImageSubData(from.tex[i], GL_TEXTURE_2D, 0, 0, 0, 0, to.tex[i], GL_TEXTURE_2D, 0, 0, 0, 0, o.width,
                         o.height, 1);
    to.latest = from.latest;
    if (to.levels > 1)
      for (int i = 0; i < 2; ++i) {
        glBindTexture(GL_TEXTURE_2D, to.tex[i]);
        glGenerateMipmap(GL_TEXTURE_2D);
      }
  }
  if (g.cube_a && o.cube_a) g.cube_a->copy_from(*o.cube_a);
}

Image PassGraph::read_buffer(int buffer) const {
  const Gpu& g = *gpu_;
  if (buffer == kCubeA) return g.cube_a->read();
  const Buffer& b = g.buffers[buffer];
  Image img;
  img.width = g.width;
  img.height = g.height;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.resize(static_cast<size_t>(g.width) * g.height * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, b.fbo[b.latest]);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, g.width, g.height, GL_RGBA, GL_FLOAT, img.pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return img;
}

void PassGraph::write_buffer(int buffer, const Image& img) {
  Gpu& g = *gpu_;
  if (buffer == kCubeA) return g.cube_a->write(img);
  ensure_buffers(img.width, img.height);
  Buffer& b = g.buffers[buffer];
  if (img.nchannels() != 4 || !b.tex[0]) fail_system("internal: a checkpoint that fits no buffer");
  glBindTexture(GL_TEXTURE_2D, b.tex[b.latest]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, img.pixels.data());
  if (b.levels > 1) glGenerateMipmap(GL_TEXTURE_2D);
}

}  // namespace ms
