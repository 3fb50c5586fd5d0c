// PassGraph's GL state (render/graph.h), internal to render/graph*.cpp:
// each buffer's pair of textures and every input's texture and sampler.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <tuple>

#include "render/audio_texture.h"
#include "render/cubemap.h"
#include "render/graph.h"
#include "render/video_texture.h"

namespace ms {

// A buffer's two textures: `latest` holds the newest complete frame, the
// other is what its pass draws next.
struct PassGraph::Buffer {
  GLuint tex[2] = {0, 0};
  GLuint fbo[2] = {0, 0};
  int latest = 0;
  int levels = 1;  // > 1 when a pass samples it mipmapped
};

// A file input's upload (texture, cubemap, volume): Shadertoy makes one
// texture per input, so two inputs of one file share an upload only when
// nothing that shapes its texels differs (row order, sRGB, channels,
// storage, mip chain); filter and wrap are sampler objects.
using UploadKey = std::tuple<const void*, bool, bool, bool, bool, bool>;
inline UploadKey upload_key(const GraphInput& in) {
  const void* data = in.kind == InputKind::cubemap  ? static_cast<const void*>(in.cube.get())
                     : in.kind == InputKind::volume ? static_cast<const void*>(in.volume.get())
                                                    : static_cast<const void*>(in.image.get());
  return {data, in.sampler.vflip, in.sampler.srgb, in.single_channel, in.eight_bit,
          in.sampler.filter == TexFilter::mipmap};
}

struct PassGraph::Gpu {
  GLuint vao = 0;
  GLuint black = 0, keyboard = 0;
  std::map<UploadKey, GLuint> textures;
  std::map<UploadKey, GLuint> volumes;
  std::map<UploadKey, GLuint> cubes;  // cubemap inputs' faces
  std::unique_ptr<CubeBuffer> cube_a;        // the Cube A pass's target, when there is one
  std::map<const AudioClip*, GLuint> audio;  // 512x2 R8, rewritten each frame
  VideoTextures videos;  // RGBA8, the frame at iTime
  std::map<int, GLuint> samplers;  // by filter * 3 + wrap
  Buffer buffers[4];
  bool used[4] = {false, false, false, false};     // made: written or read
  bool written[4] = {false, false, false, false};  // some pass draws it
  int width = 0, height = 0;
};

// A full mip chain's level count for a w x h texture.
inline int mip_levels(int w, int h) { return 1 + static_cast<int>(std::floor(std::log2(std::max({w, h, 1})))); }

}  // namespace ms
