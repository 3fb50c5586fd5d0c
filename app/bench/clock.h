// The clocks bench, sweep and test time frames with.
#pragma once
#include <chrono>
#include <ctime>

namespace ms {

// CPU time of the whole process (every thread: llvmpipe's included), ms.
// On a software GL the frame's work is this process's threads, so this
// barely moves when other processes load a shared machine.
inline double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

inline double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace ms
