// The GL side of video inputs: one GL_TEXTURE_2D per video stream, RGBA8
// (sRGB when the sampler asks), rewritten once per frame with the frame
// that shows at iTime (io/video_input.h), rows bottom first when vflip
// (Shadertoy's default for video, as for textures: uv (0,0) at the
// picture's lower left); mipmaps regenerated per frame when any pass
// samples it mipmapped. Needs the GL context current.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include "gl/gl.h"
#include "io/video_input.h"
#include "scene/project.h"

namespace ms {

class VideoTextures {
 public:
  VideoTextures() = default;
  ~VideoTextures();
  VideoTextures(const VideoTextures&) = delete;
  VideoTextures& operator=(const VideoTextures&) = delete;

  // A channel that shows `video` with `sampler`; the first channel of a
  // stream sets its vflip and sRGB (a project's streams are made per file,
  // vflip and sRGB: pipeline/project_passes.cpp).
  void add(const std::shared_ptr<VideoStream>& video, const Sampler& sampler);
  // Each texture to the frame at `t`; waits on ffmpeg within `deadline`.
  void update(double t, const Deadline* deadline);
  GLuint texture(const VideoStream* video) const { return textures_.at(video).tex; }

 private:
  struct Tex {
    std::shared_ptr<VideoStream> video;
    GLuint tex = 0;
    int levels = 1;
    bool vflip = true;
    long shown = -1;  // the frame index uploaded
  };
  std::map<const VideoStream*, Tex> textures_;
  std::vector<std::uint8_t> flipped_;
};

}  // namespace ms
