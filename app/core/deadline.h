// Bounded work (--timeout): a Deadline that long-running loops check between
// steps, and a Watchdog thread that ends the process when a step itself
// never returns (a GL draw of a shader that loops forever cannot be
// interrupted from inside the process: llvmpipe's rasterizer threads spin,
// and a GPU driver may wait seconds before its own reset).
#pragma once
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace ms {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  // No limit.
  Deadline() = default;
  // `seconds` from now; <= 0 or non-finite means no limit.
  static Deadline after(double seconds);

  bool limited() const { return limited_; }
  bool expired() const { return limited_ && Clock::now() >= at_; }
  double seconds() const { return seconds_; }  // the limit it was made with (0: none)
  Clock::time_point at() const { return at_; }
  // Throws timeout_error(what) once expired.
  void check(const std::string& what) const;

 private:
  bool limited_ = false;
  double seconds_ = 0.0;
  Clock::time_point at_{};
};

// The one error for an exceeded --timeout: Exit::system (the work may be
// fine, the budget was not enough), key "--timeout", "<what> did not finish
// within N s". The Watchdog prints the same line.
[[noreturn]] void fail_timeout(const std::string& what, double seconds);
std::string timeout_message(const std::string& what, double seconds);

// While armed, ends the process with Exit::system after the deadline plus a
// grace period, printing "marchstudio: <timeout message>" on stderr: the
// grace gives the cooperative check (Deadline::check between draws) the
// chance to fail cleanly first. Before exiting it runs `before_exit` (e.g.
// wait for frames already handed to the writer). Files are written
// atomically (temporary + rename) and the watchdog is disarmed before the
// final write starts, so it never leaves a partial output file.
class Watchdog {
 public:
  explicit Watchdog(double grace_seconds = 0.5);
  ~Watchdog();  // disarms and joins
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  // Arm (or re-arm) for `d`; a deadline without a limit disarms.
  void arm(const Deadline& d, std::string what, std::function<void()> before_exit = {});
  void disarm();

 private:
  void run();

  const std::chrono::duration<double> grace_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool armed_ = false, stop_ = false;
  Deadline deadline_;
  std::string what_;
  std::function<void()> before_exit_;
  std::thread thread_;  // last: starts after the members above exist
};

}  // namespace ms
