// A job's --timeout in one place: its Deadline, checked between steps, and
// a Watchdog that ends the process when a step itself never returns (a
// draw of a shader that loops forever), both armed together and disarmed
// together before the atomic write, which must not be cut short. Used by
// the still, each frame of a sequence and the mesh export.
//
//   GuardedJob guard(job.timeout, "the render");
//   fp.deadline = guard.limit();      // checked between draws
//   ...                               // draw
//   guard.finish();                   // watchdog off; past the deadline: the timeout error
//   write_image(img, output, meta);   // atomic
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "core/deadline.h"

namespace ms {

class GuardedJob {
 public:
  // `seconds` <= 0 or not finite: no limit, no watchdog. `before_exit` runs
  // before the watchdog ends the process (e.g. finish frames already queued).
  GuardedJob(double seconds, std::string what, std::function<void()> before_exit = {});
  GuardedJob(const GuardedJob&) = delete;
  GuardedJob& operator=(const GuardedJob&) = delete;

  // A new step with a budget of its own (a sequence's next frame): the
  // deadline restarts from now and the watchdog is armed for it.
  void restart(std::string what, std::function<void()> before_exit = {});

  const Deadline& deadline() const { return deadline_; }
  // For FrameParams::deadline: null when there is no limit.
  const Deadline* limit() const { return deadline_.limited() ? &deadline_ : nullptr; }
  // For a writer that re-arms it with its own hook (pipeline/tiled_render.h).
  Watchdog* watchdog() { return watchdog_ ? &*watchdog_ : nullptr; }
  const std::string& what() const { return what_; }

  // Throws the timeout error once past the deadline.
  void check() const { deadline_.check(what_); }
  // The watchdog off, e.g. before an exception unwinds what its hook names.
  void disarm();
  // Before the atomic write: the watchdog off, then the timeout error if
  // the work ran past the deadline (nothing is written).
  void finish();

 private:
  double seconds_;
  std::string what_;
  Deadline deadline_;
  std::optional<Watchdog> watchdog_;
};

}  // namespace ms
