#include "pipeline/guarded_job.h"

#include <utility>

namespace ms {

GuardedJob::GuardedJob(double seconds, std::string what, std::function<void()> before_exit)
    : seconds_(seconds), what_(std::move(what)), deadline_(Deadline::after(seconds)) {
  if (deadline_.limited()) watchdog_.emplace().arm(deadline_, what_, std::move(before_exit));
}

void GuardedJob::restart(std::string what, std::function<void()> before_exit) {
  what_ = std::move(what);
  deadline_ = Deadline::after(seconds_);
  if (watchdog_) watchdog_->arm(deadline_, what_, std::move(before_exit));
}

void GuardedJob::disarm() {
  if (watchdog_) watchdog_->disarm();
}

void GuardedJob::finish() {
  disarm();
  check();
}

}  // namespace ms
