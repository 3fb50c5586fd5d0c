// Recording from the viewer (F9, or view --record A..B): while it runs,
// time no longer follows the clock; window frame k shows frame f = first + k
// at exactly f / fps, and each is re-rendered at the scene's spp through the
// screenshot path (FrameDrawer::screenshot, render's own) into
// DIR/frame_%04d.png. So the files equal `render --frames first..last
// --fps F` at the same size. On stop, with --record-video FILE and ffmpeg on
// PATH, the frames are encoded as render --video does (io/video.h).
//
//   Recorder rec(options);
//   rec.start(time, shadertoy, stateful, log);    // or stop(log)
//   if (rec.active()) state.time = rec.time();    // before the frame is drawn
//   rec.frame(drawer, w, h, log);                 // after it is drawn
#pragma once
#include <filesystem>
#include <string>

#include "live/live_log.h"

namespace ms::live {

class FrameDrawer;  // live/viewer_frame.h

struct RecordOptions {
  std::filesystem::path dir;    // where the frames go
  double fps = 0.0;             // 0: render's default, 24 (a Shadertoy shader's 60)
  int first = -1, last = -1;    // --record A..B; -1: from the time at F9, until F9 again
  std::filesystem::path video;  // encode on stop; empty: frames only
};

class Recorder {
 public:
  explicit Recorder(const RecordOptions& o) : o_(o) {}

  // Starts at frame o.first, or the frame at `time`. Returns the message
  // to show; a shader with buffers is refused (its buffers step with the
  // window's frames: use render --frames).
  std::string start(double time, bool shadertoy, bool stateful, LiveLog& log);
  // Ends it (and encodes the video when asked); the message to show.
  std::string stop(LiveLog& log);

  bool active() const { return active_; }
  int frame() const { return frame_; }
  double time() const { return frame_ / fps_; }  // the time of the frame drawn next
  // Writes the frame just drawn at time(), then moves to the next; stops
  // after o.last. Returns a message when it stopped, else empty.
  std::string frame(FrameDrawer& drawer, int width, int height, LiveLog& log);

 private:
  RecordOptions o_;
  bool active_ = false;
  int first_ = 0, frame_ = 0;
  double fps_ = 24.0;
};

}  // namespace ms::live
