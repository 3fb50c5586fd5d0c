#include "render/video_texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ms {

VideoTextures::~VideoTextures() {
  for (auto& [v, t] : textures_) glDeleteTextures(1, &t.tex);
}

void VideoTextures::add(const std::shared_ptr<VideoStream>& video, const Sampler& sampler) {
  const VideoInfo& info = video->info();
  const int levels = sampler.filter == TexFilter::mipmap
                         ? 1 + static_cast<int>(std::floor(std::log2(std::max({info.width, info.height, 1}))))
                         : 1;
  auto it = textures_.find(video.get());
  if (it != textures_.end()) {
    if (levels <= it->second.levels) return;
    glDeleteTextures(1, &it->second.tex);  // a later channel samples it mipmapped: made again with levels
  } else {
    it = textures_.emplace(video.get(), Tex{video, 0, 1, sampler.vflip, -1}).first;
  }
  Tex& t = it->second;
  t.levels = levels;
  t.shown = -1;
  glGenTextures(1, &t.tex);
  glBindTexture(GL_TEXTURE_2D, t.tex);
  glTexStorage2D(GL_TEXTURE_2D, levels, sampler.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, info.width, info.height);
}

void VideoTextures::update(double t, const Deadline* deadline) {
  for (auto& [v, tex] : textures_) {
    const long n = tex.video->frame_index(t);
    if (n == tex.shown) continue;
    const std::vector<std::uint8_t>& rgba = tex.video->frame(n, deadline);
    const int w = tex.video->info().width, h = tex.video->info().height;
    const std::uint8_t* data = rgba.data();
    if (tex.vflip) {  // GL's row 0 is uv's v = 0: the picture's bottom row
      const size_t row = static_cast<size_t>(w) * 4;
      flipped_.resize(rgba.size());
      for (int y = 0; y < h; ++y) std::memcpy(flipped_.data() + y * row, rgba.data() + (h - 1 - y) * row, row);
      data = flipped_.data();
    }
    glBindTexture(GL_TEXTURE_2D, tex.tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, data);
    if (tex.levels > 1) glGenerateMipmap(GL_TEXTURE_2D);
    tex.shown = n;
  }
}

}  // namespace ms
