// Video files as frames: what a Shadertoy video input shows. Decoded by
// ffmpeg run as a child (no shell), when it is on PATH: probed once for its
// size, rate and duration (ffprobe if present, else ffmpeg's own report),
// then streamed as raw RGBA through a pipe by one ffmpeg that decodes
// forward; a backwards step, a loop or a jump far ahead restarts it with a
// seek. Which frame shows at a time is a function of the time alone
// (video_frame_index), so a still and a sequence's frame agree.
//
//   VideoStream v = open_video("clip.webm");       // throws bad_input naming it
//   const auto& rgba = v.frame(v.frame_index(t), deadline);  // top row first
#pragma once
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/deadline.h"

namespace ms {

struct VideoInfo {
  int width = 0, height = 0;
  double fps = 0.0;       // frames a second: the stream's average rate
  double duration = 0.0;  // seconds: the loop's period
  long frames = 0;        // frames in one period: round(duration x fps), at least 1
};

// The frame that shows at time `t` (seconds; before 0 is frame 0): the
// video loops with period `duration`, frame n shows from n / fps, and the
// last one holds to the end of the period. 1e-4 of a frame of slack, so
// that t = n / fps in float shows frame n.
long video_frame_index(const VideoInfo& info, double t);

class VideoStream {
 public:
  VideoStream(std::filesystem::path ffmpeg, std::filesystem::path file, VideoInfo info);
  ~VideoStream();  // ends the decoder
  VideoStream(const VideoStream&) = delete;
  VideoStream& operator=(const VideoStream&) = delete;

  const VideoInfo& info() const { return info_; }
  const std::filesystem::path& file() const { return file_; }
  long frame_index(double t) const { return video_frame_index(info_, t); }
  // Frame n (0..frames-1) as width x height RGBA8, the file's top row
  // first. A frame past what ffmpeg decodes is the last it decoded. Throws
  // bad_input naming the file when no frame decodes, the --timeout error
  // when `deadline` passes while waiting.
  const std::vector<std::uint8_t>& frame(long n, const Deadline* deadline = nullptr);

 private:
  void start(long n);  // a decoder whose first frame is frame n
  void stop();
  bool read_next(const Deadline* deadline);  // one frame into next_pixels_; false at the end of the stream

  std::filesystem::path ffmpeg_, file_;
  VideoInfo info_;
  pid_t pid_ = -1;
  int fd_ = -1;
  long next_ = 0;        // the index of the frame the decoder gives next
  long have_ = -1;       // the index of pixels_ (-1: none)
  long end_ = -1;        // the first index past the decoded stream, once known
  std::vector<std::uint8_t> pixels_, next_pixels_;
};

// Bounds of their own on each ffmpeg child, whatever --timeout says, so a
// file that makes one wait (a concat script naming a FIFO) is refused, not
// waited for: a probe (ffprobe, or ffmpeg -i) has kVideoProbeSeconds; a
// decoder that sends no byte for kVideoStallSeconds is ended. Either is
// one line naming the file, exit 2.
inline constexpr double kVideoProbeSeconds = 10.0;
inline constexpr double kVideoStallSeconds = 30.0;

// ffmpeg from PATH, probed: the stream for `file`. ffmpeg not on PATH, a
// file it cannot decode or one with no video: bad_input, one line. `where`
// names the channel in the error ("Image iChannel0").
std::shared_ptr<VideoStream> open_video(const std::filesystem::path& file, const std::string& where);

}  // namespace ms
