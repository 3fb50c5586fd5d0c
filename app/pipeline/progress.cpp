#include "pipeline/progress.h"

#include <cmath>
#include <utility>

#include "core/utf8.h"

namespace ms {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "-";
  const long long s = std::llround(seconds);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lld:%02lld", s / 60, s % 60);
  return buf;
}

std::string format_frame_time(double seconds) {
  char buf[32];
  // About three significant digits: a small frame on a fast device takes well under a millisecond.
  const double ms = seconds * 1e3;
  if (seconds >= 1.0) std::snprintf(buf, sizeof buf, "%.2f s", seconds);
  else std::snprintf(buf, sizeof buf, "%.*f ms", ms >= 100.0 ? 0 : ms >= 10.0 ? 1 : ms >= 1.0 ? 2 : 3, ms);
  return buf;
}

Progress::Progress(int total, bool tty, std::FILE* out, std::string unit, std::string verb)
    : total_(total), tty_(tty), unit_(std::move(unit)), verb_(std::move(verb)), out_(out) {}

void Progress::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  start_ = Clock::now();
}

void Progress::skipped(int frame, const std::string& path) {
  // On a terminal the summary line says how many were skipped; a line per
  // frame would scroll the bar away on a large resume.
  if (tty_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(out_, "marchstudio: frame %d skipped: %s is complete\n", frame, path.c_str());
  std::fflush(out_);
}

void Progress::redo(int frame, const std::string& path, const std::string& why) {
  line("frame " + std::to_string(frame) + ": " + path + " is not a complete frame (" + why + "), rendering it again");
}

void Progress::rendered(int frame, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (tty_) {
    draw_locked(frame);
    return;
  }
  if (unit_ != "frames") return;
  const double elapsed = seconds_since(start_);
  const double fps = elapsed > 0 ? done_ / elapsed : 0.0;
  std::fprintf(out_, "marchstudio: frame %d %s in %s (%d/%d, %.2f frames/s, ETA %s)\n", frame, verb_.c_str(),
               format_frame_time(seconds).c_str(), done_, total_, fps,
               format_duration(fps > 0 ? (total_ - done_) / fps : -1).c_str());
  std::fflush(out_);
}

void Progress::draw_locked(int frame) {
  constexpr int kWidth = 30;
  const double elapsed = seconds_since(start_);
  const double fps = elapsed > 0 ? done_ / elapsed : 0.0;
  const int filled = total_ > 0 ? done_ * kWidth / total_ : kWidth;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  // \r and "erase to end of line": the bar redraws over itself.
  const std::string eta = format_duration(fps > 0 ? (total_ - done_) / fps : -1);
  if (unit_ == "frames")
    std::fprintf(out_, "\r[%s] %d/%d frames  %.2f fps  ETA %s  (frame %d)\x1b[K", bar.c_str(), done_, total_, fps,
                 eta.c_str(), frame);
  else
    std::fprintf(out_, "\r[%s] %d/%d %s  %.2f %s/s  ETA %s\x1b[K", bar.c_str(), done_, total_, unit_.c_str(), fps,
                 unit_.c_str(), eta.c_str());
  std::fflush(out_);
  bar_shown_ = true;
}

void Progress::line(const std::string& text) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (bar_shown_) std::fprintf(out_, "\r\x1b[K");
  std::fprintf(out_, "marchstudio: %s\n", valid_utf8(text).c_str());
  std::fflush(out_);
  bar_shown_ = false;
}

void Progress::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (bar_shown_) std::fprintf(out_, "\n");
  bar_shown_ = false;
  std::fflush(out_);
}

}  // namespace ms
