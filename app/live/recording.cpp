#include "live/recording.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "io/video.h"
#include "live/viewer_frame.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

std::string frame_name(int f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%04d.png", f);
  return buf;
}

}  // namespace

std::string Recorder::start(double time, bool shadertoy, bool stateful, LiveLog& log) {
  if (active_) return {};
  if (stateful) {
    log.line("record refused -- a shader with buffers");
    return "not recording: a shader's buffers step with the window's frames; use render --frames";
  }
  fps_ = o_.fps > 0.0 ? o_.fps : shadertoy ? 60.0 : 24.0;  // render --fps's default
  first_ = frame_ = o_.first >= 0 ? o_.first : static_cast<int>(std::lround(time * fps_));
  std::error_code ec;
  fs::create_directories(o_.dir, ec);
  if (ec) {
    log.line("record failed -- " + ec.message());
    return "not recording: cannot make " + o_.dir.string() + ": " + ec.message();
  }
  active_ = true;
  log.line("record start " + std::to_string(first_) + " fps=" + std::to_string(fps_) + " " + o_.dir.string());
  return "recording from frame " + std::to_string(first_) + " at " + std::to_string(static_cast<int>(fps_)) +
         " fps into " + o_.dir.string() + " (F9 stops)";
}

std::string Recorder::frame(FrameDrawer& drawer, int width, int height, LiveLog& log) {
  if (!active_) return {};
  const fs::path path = o_.dir / frame_name(frame_);
  try {
    drawer.screenshot(path, width, height);
    log.line("record " + std::to_string(frame_) + " " + path.string());
  } catch (const Error& e) {
    log.line("record " + std::to_string(frame_) + " failed -- " + e.what());
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    return stop(log);
  }
  ++frame_;
  if (o_.last >= 0 && frame_ > o_.last) return stop(log);
  return {};
}

std::string Recorder::stop(LiveLog& log) {
  if (!active_) return {};
  active_ = false;
  const int n = frame_ - first_;
  log.line("record done " + std::to_string(n) + " frames " + o_.dir.string());
  std::string msg = "recorded " + std::to_string(n) + " frames into " + o_.dir.string();
  if (o_.video.empty() || n == 0) return msg;
  const fs::path ffmpeg = find_on_path("ffmpeg");
  if (ffmpeg.empty()) {
    log.line("record video failed -- ffmpeg is not on PATH");
    return msg + "; no video: ffmpeg is not on PATH";
  }
  try {
    VideoJob job;
    job.ffmpeg = ffmpeg;
    job.pattern = (o_.dir / "frame_%04d.png").string();
    job.first_frame = first_;
    job.fps = fps_;
    job.output = o_.video;
    job.frames = n;
    encode_video(job);
    log.line("record video " + o_.video.string());
    return msg + " and " + o_.video.string();
  } catch (const Error& e) {
    log.line(std::string("record video failed -- ") + e.what());
    return msg + "; no video: " + e.what();
  }
}

}  // namespace ms::live
