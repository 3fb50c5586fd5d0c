// Progress of a sequence render, or of a tiled still's tiles, on stderr:
// on a terminal one line redrawn in place (a bar, frames done, frames per
// second, ETA); otherwise (logs, CI, Slurm output files) one plain line per
// event, which is also what tests read. Thread-safe: frames are reported
// from the render loop and writes from the writer thread.
#pragma once
#include <cstdio>
#include <mutex>
#include <string>

#include "core/clock.h"

namespace ms {

// "1:02:03" or "2:03"; "-" when unknown.
std::string format_duration(double seconds);
// A frame's render time: "1.25 s", "71.2 ms", "0.412 ms".
std::string format_frame_time(double seconds);

class Progress {
 public:
  // `total`: the frames this process will render (skipped ones excluded).
  // `unit` "tiles" counts a tiled still's tiles (render/tiled_still.h):
  // the bar alone, on a terminal; a log gets no line per tile. `verb`
  // says what became of a frame in a log's line ("meshed" for meshes).
  Progress(int total, bool tty, std::FILE* out = stderr, std::string unit = "frames", std::string verb = "rendered");

  // Restart the clock for frames/s and ETA (when the first frame starts).
  void start();
  // A frame a previous run already finished.
  void skipped(int frame, const std::string& path);
  // A frame found broken, cut short or of another size, rendered again.
  void redo(int frame, const std::string& path, const std::string& why);
  // A frame rendered and queued for writing; `seconds`: its render time.
  void rendered(int frame, double seconds);
  // Any other line (warnings, the summary); clears the bar first on a TTY.
  void line(const std::string& text);
  // Ends the bar's line on a TTY.
  void finish();

  int done() const { return done_; }

 private:
  void draw_locked(int frame);

  const int total_;
  const bool tty_;
  const std::string unit_;
  const std::string verb_;
  std::FILE* const out_;
  std::mutex mutex_;
  int done_ = 0;
  bool bar_shown_ = false;
  Clock::time_point start_ = Clock::now();
};

}  // namespace ms
