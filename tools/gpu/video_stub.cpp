// The lean GPU bench has no ffmpeg beside it (and no io/ module): a shader
// with a video input is refused in one line (io/video_input.h), so no
// stream is ever made and the rest stays empty here.
#include "core/error.h"
#include "io/video_input.h"

namespace ms {

long video_frame_index(const VideoInfo&, double) { return 0; }

VideoStream::~VideoStream() = default;

const std::vector<std::uint8_t>& VideoStream::frame(long, const Deadline*) { return pixels_; }

std::shared_ptr<VideoStream> open_video(const std::filesystem::path& file, const std::string& where) {
  fail_input(where + ": the GPU bench does not read video inputs (use the full marchstudio)", file.string());
}

}  // namespace ms
