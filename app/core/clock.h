// The one clock every timing the program reports is read from: steady
// (never the wall clock, which can jump), plus the process's CPU time.
#pragma once
#include <chrono>
#include <ctime>

namespace ms {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

inline double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Seconds from a fixed, arbitrary origin: timestamps that are only ever
// subtracted from each other (frame pacing, debounce).
inline double clock_seconds() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

// A timer started at construction: the time since then, or since the last lap.
class Stopwatch {
 public:
  double seconds() const { return seconds_since(start_); }
  double ms() const { return ms_since(start_); }
  // Seconds since the previous lap (the start for the first), for phase timings.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - lap_).count();
    lap_ = now;
    return s;
  }

 private:
  Clock::time_point start_ = Clock::now();
  Clock::time_point lap_ = start_;
};

// CPU time of the whole process (every thread: llvmpipe's included), ms.
// On a software GL the frame's work is this process's threads, so this
// barely moves when other processes load a shared machine.
inline double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

}  // namespace ms
