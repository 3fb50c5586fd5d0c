// The extension's job thread and its Ctrl-C scope (docs/python.md#ctrl-c-and-threads),
// included once, by marchstudio_ext.cpp.
#pragma once
#include <nanobind/nanobind.h>

#include <condition_variable>
#include <csignal>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <pthread.h>
#include <thread>

namespace marchstudio_py {
namespace nb = nanobind;

class GlThread {
 public:
  GlThread() {
    // Started with every signal blocked: Ctrl-C goes to Python's threads.
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    std::thread([this] { loop(); }).detach();
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
  }
  // Runs `job` there and waits for it (the caller has released the GIL);
  // its exception comes back here.
  void run(const std::function<void()>& job) {
    std::packaged_task<void()> task(job);
    std::future<void> done = task.get_future();
    {
      std::lock_guard<std::mutex> hold(lock_);
      queue_.push_back(&task);
    }
    ready_.notify_one();
    done.get();
  }

 private:
  void loop() {
    for (;;) {
      std::packaged_task<void()>* task;
      {
        std::unique_lock<std::mutex> hold(lock_);
        ready_.wait(hold, [this] { return !queue_.empty(); });
        task = queue_.front();
        queue_.pop_front();
      }
      (*task)();
    }
  }
  std::mutex lock_;
  std::condition_variable ready_;
  std::deque<std::packaged_task<void()>*> queue_;
};

inline GlThread& gl_thread() {
  static GlThread* t = new GlThread;  // never joined, as the context is never torn down
  return *t;
}

// Ctrl-C while a job runs without the GIL: Python's own handler only
// trips a flag that the interpreter reads once the job returns. For the
// job's life this handler also notes the signal where the job's progress
// callback can see it (the mesh job then stops between stages), and chains
// to Python's, so KeyboardInterrupt follows once the GIL is back. The jobs'
// own scopes (io/temp_cleanup.h, while a file is written) nest inside.
inline volatile std::sig_atomic_t g_interrupted = 0;
inline struct sigaction g_python_int {};

extern "C" inline void note_interrupt(int sig) {
  g_interrupted = 1;
  if (g_python_int.sa_handler != SIG_DFL && g_python_int.sa_handler != SIG_IGN) g_python_int.sa_handler(sig);
}

struct Interrupted {};  // thrown by a job's progress callback after Ctrl-C
inline int users_of_interrupt_scope = 0;

class InterruptScope {
 public:
  // Made and destroyed with the GIL held, which orders them: the first of
  // the threads waiting on jobs installs the handler, the last puts
  // Python's back (a second install would chain the handler to itself).
  InterruptScope() {
    if (users_of_interrupt_scope++ > 0) return;
    g_interrupted = 0;
    sigaction(SIGINT, nullptr, &g_python_int);
    if (g_python_int.sa_handler == SIG_IGN) return;  // ignored (a background job): left so
    struct sigaction sa {};
    sa.sa_handler = note_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &g_python_int);
  }
  ~InterruptScope() {
    if (--users_of_interrupt_scope == 0 && g_python_int.sa_handler != SIG_IGN)
      sigaction(SIGINT, &g_python_int, nullptr);
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  // With the GIL, after a job: on Python's main thread, the signal's own
  // handler runs (KeyboardInterrupt by default); on another thread, whose
  // job `cut_short` was stopped unfinished, KeyboardInterrupt, and the
  // signal is left to the main thread, where Python runs its handlers.
  static void raise_if_interrupted(bool cut_short) {
    if (!g_interrupted) return;
    const bool main = nb::module_::import_("threading").attr("main_thread")().attr("ident").equal(
        nb::int_(PyThread_get_thread_ident()));
    if (main) {
      g_interrupted = 0;
      if (PyErr_CheckSignals() != 0) throw nb::python_error();
    }
    if (!cut_short) return;
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw nb::python_error();
  }
};

}  // namespace marchstudio_py
