// The GL side of cubemaps (docs/shadertoy.md#cubemaps): a cubemap input's
// six faces as one GL_TEXTURE_CUBE_MAP, and the Cube A pass's target, a
// ping-pong pair of RGBA16F cubes of 1024 x 1024 faces (Shadertoy's
// size and format), drawn one face at a time. Needs the GL context current.
#pragma once
#include <functional>

#include "core/deadline.h"
#include "gl/gl.h"
#include "io/cube_faces.h"
#include "io/image.h"
#include "scene/project.h"

namespace ms {

// Shadertoy's Cube A face size.
inline constexpr int kCubeFaceSize = 1024;

// Six faces as a cube map: RGBA8 (SRGB8_ALPHA8 for srgb) or RGBA32F, a
// face's top row at t = 0 (flipped when the sampler asks for vflip), mip
// chain when sampled mipmapped.
GLuint upload_cube(const CubeFaces& faces, const Sampler& sampler);

class CubeBuffer {
 public:
  // `levels` > 1: a pass samples it mipmapped, the chain follows each draw.
  explicit CubeBuffer(int levels = 1, int size = kCubeFaceSize);
  ~CubeBuffer();
  CubeBuffer(const CubeBuffer&) = delete;
  CubeBuffer& operator=(const CubeBuffer&) = delete;

  int size() const { return size_; }
  GLuint texture() const { return tex_[latest_]; }  // the newest complete frame
  // Both cubes to 0, as before frame 0.
  void clear();
  // One frame: `setup(face)` after the face's framebuffer, viewport and
  // program are bound (it binds inputs and sets uniforms), then a draw of
  // the full-screen triangle, for faces 0..5 into the other cube, which
  // then becomes the newest. A deadline is checked after each face.
  void draw(GLuint program, GLuint vao, const std::function<void(int face)>& setup, const Deadline* deadline);
  // Faces +X..-Z stacked top to bottom: size x 6 size RGBA float, each
  // face in GL's row order; write() takes the same back (checkpoints).
  Image read() const;
  void write(const Image& img);
  // Both cubes of `other`, copied on the GPU (a viewer reload).
  void copy_from(const CubeBuffer& other);

 private:
  void mipmaps(int which);
  int size_ = 0, levels_ = 1, latest_ = 0;
  GLuint tex_[2] = {0, 0};
  GLuint fbo_ = 0;
};

}  // namespace ms
