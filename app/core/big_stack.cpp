#include "core/big_stack.h"

#include <pthread.h>
#include <signal.h>

#include <exception>

namespace ms {
namespace {

struct Call {
  const std::function<int()>* fn;
  int result = 0;
  std::exception_ptr error;
};

void* trampoline(void* arg) {
  Call* c = static_cast<Call*>(arg);
  try {
    c->result = (*c->fn)();
  } catch (...) {
    c->error = std::current_exception();
  }
  return nullptr;
}

bool run_with(Call& call, std::size_t bytes) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return false;
  pthread_t thread;
  const bool made = pthread_attr_setstacksize(&attr, bytes) == 0 &&
                    pthread_create(&thread, &attr, trampoline, &call) == 0;
  pthread_attr_destroy(&attr);
  if (!made) return false;
  // Signals sent to the process go to the thread that runs the program, as
  // they went to the main thread before: there, handlers and signalfd
  // masks (render --watch, sequences) see them. This thread only waits.
  sigset_t all, old;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &old);
  pthread_join(thread, nullptr);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return true;
}

}  // namespace

int run_on_big_stack(const std::function<int()>& fn, std::size_t bytes) {
  Call call{&fn, 0, nullptr};
  bool ran = false;
  for (std::size_t b = bytes; !ran && b >= (std::size_t{16} << 20); b /= 4) ran = run_with(call, b);
  if (!ran) return fn();
  if (call.error) std::rethrow_exception(call.error);
  return call.result;
}

}  // namespace ms
