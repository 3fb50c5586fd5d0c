#include "core/deadline.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/format.h"

namespace ms {

Deadline Deadline::after(double seconds) {
  Deadline d;
  if (!(seconds > 0.0) || !std::isfinite(seconds)) return d;
  d.limited_ = true;
  d.seconds_ = seconds;
  // The clock counts nanoseconds in 64 bits (292 years): a longer limit
  // would wrap into the past and expire at once. Beyond a century, a
  // century: no limit in practice, and room for the watchdog's grace.
  constexpr double kCentury = 100.0 * 365.25 * 24 * 3600;
  d.at_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(std::min(seconds, kCentury)));
  return d;
}

void Deadline::check(const std::string& what) const {
  if (expired()) fail_timeout(what, seconds_);
}

namespace {

ErrorInfo timeout_info(const std::string& what, double seconds) {
  return ErrorInfo{Exit::system, {}, 0, "--timeout", what + " did not finish within " + format_number(seconds) + " s",
                   "a shader loop that never ends, or more work than the time allows", {}};
}

}  // namespace

std::string timeout_message(const std::string& what, double seconds) {
  return format_error(timeout_info(what, seconds));
}

void fail_timeout(const std::string& what, double seconds) { throw Error(timeout_info(what, seconds)); }

Watchdog::Watchdog(double grace_seconds) : grace_(grace_seconds), thread_([this] { run(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    armed_ = false;
  }
  changed_.notify_all();
  thread_.join();
}

void Watchdog::arm(const Deadline& d, std::string what, std::function<void()> before_exit) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    armed_ = d.limited();
    deadline_ = d;
    what_ = std::move(what);
    before_exit_ = std::move(before_exit);
  }
  changed_.notify_all();
}

void Watchdog::disarm() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    armed_ = false;
  }
  changed_.notify_all();
}

void Watchdog::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (stop_) return;
    if (!armed_) {
      changed_.wait(lock);
      continue;
    }
    const auto fire_at = deadline_.at() + std::chrono::duration_cast<Deadline::Clock::duration>(grace_);
    if (changed_.wait_until(lock, fire_at) == std::cv_status::no_timeout || !armed_ || stop_) continue;
    if (Deadline::Clock::now() < fire_at) continue;  // spurious
    // The main thread is stuck (most likely inside a draw): no exception can
    // reach it, so report and leave from here. _exit skips destructors that
    // would wait for the stuck GL threads.
    const std::string line = "marchstudio: " + timeout_message(what_, deadline_.seconds()) + "\n";
    std::function<void()> before = before_exit_;
    lock.unlock();
    if (before) {
      try {
        before();
      } catch (...) {
      }
    }
    const ssize_t ignored = ::write(2, line.data(), line.size());
    (void)ignored;
    ::_exit(static_cast<int>(Exit::system));
  }
}

}  // namespace ms
