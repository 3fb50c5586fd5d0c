// One handler for SIGINT and SIGTERM (Ctrl-C; what Slurm's scancel and time
// limit send first) for the life of a scope; the previous handlers come back
// at its end. The handler may only call async-signal-safe functions.
//
//   extern "C" void on_stop(int sig) { g_stop = sig; }
//   SignalScope stop(on_stop, SA_RESETHAND);  // a second signal kills at once
#pragma once
#include <csignal>

namespace ms {

class SignalScope {
 public:
  explicit SignalScope(void (*handler)(int), int flags = 0) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sa.sa_flags = flags;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~SignalScope() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  SignalScope(const SignalScope&) = delete;
  SignalScope& operator=(const SignalScope&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace ms
