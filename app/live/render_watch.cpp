#include "live/render_watch.h"

#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/clock.h"
#include "core/error.h"
#include "live/watcher.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

// SIGINT/SIGTERM arrive on a file descriptor (signalfd) instead of a
// handler, so stopping needs no global flag and never interrupts a render
// halfway through writing its file.
class SignalFd {
 public:
  SignalFd() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    if (sigprocmask(SIG_BLOCK, &set_, &old_) != 0) fail_system("sigprocmask failed");
    fd_ = signalfd(-1, &set_, SFD_CLOEXEC | SFD_NONBLOCK);
    if (fd_ < 0) {
      sigprocmask(SIG_SETMASK, &old_, nullptr);
      fail_system(std::string("signalfd: ") + std::strerror(errno));
    }
  }
  ~SignalFd() {
    ::close(fd_);
    sigprocmask(SIG_SETMASK, &old_, nullptr);
  }
  int fd() const { return fd_; }
  void consume() {
    signalfd_siginfo info;
    while (::read(fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
    }
  }

 private:
  sigset_t set_{}, old_{};
  int fd_ = -1;
};

bool contains(const std::vector<fs::path>& files, const std::string& file) {
  if (file.empty()) return false;
  std::error_code ec;
  const fs::path f = fs::weakly_canonical(fs::absolute(file, ec), ec);
  for (const fs::path& p : files)
    if (fs::weakly_canonical(fs::absolute(p, ec), ec) == f) return true;
  return false;
}

std::vector<fs::path> files_or(const WatchRenderOptions& o, const std::vector<fs::path>& previous, bool& ok) {
  try {
    ok = true;
    return o.files();
  } catch (const Error& e) {
    ok = false;
    std::vector<fs::path> out = previous;
    if (!e.info().file.empty()) out.push_back(e.info().file);
    return out;
  }
}

}  // namespace

int watch_and_render(const WatchRenderOptions& o) {
  SignalFd signals;
  Watcher watcher;
  std::vector<fs::path> files;
  for (int n = 1;; ++n) {
    const Stopwatch t0;
    std::optional<Error> failure;
    try {
      o.render();
    } catch (const Error& e) {
      failure = e;
    }
    const bool ok = !failure;
    const double ms = t0.ms();
    bool files_ok = true;
    files = files_or(o, files, files_ok);
    if (failure) {
      // A first failure outside the watched files (a bad flag, a missing
      // output directory, no GL) cannot be fixed by saving: end as `render`.
      if (n == 1 && !contains(files, failure->info().file)) throw *failure;
      std::fprintf(stderr, "marchstudio: %s\n", failure->what());
    }
    watcher.watch(files);
    watcher.set_match_any(!ok || !files_ok);
    std::fprintf(stderr, "marchstudio: watch: render %d %s (%.0f ms); watching %zu files, Ctrl+C stops\n", n,
                 ok ? "ok" : "failed", ms, watcher.files().size());
    std::fflush(stdout);
    // Wait for a save or a signal.
    for (;;) {
      pollfd fds[2] = {{watcher.fd(), POLLIN, 0}, {signals.fd(), POLLIN, 0}};
      if (::poll(fds, 2, -1) < 0) {
        if (errno == EINTR) continue;
        fail_system(std::string("poll: ") + std::strerror(errno));
      }
      if (fds[1].revents & POLLIN) {
        signals.consume();  // else it fires again once the mask is restored
        std::fprintf(stderr, "marchstudio: watch: stopped\n");
        return 0;
      }
      std::vector<fs::path> changed = watcher.poll();
      if (changed.empty()) continue;
      watcher.settle(changed, o.debounce_ms, 100);
      break;
    }
  }
}

}  // namespace ms::live
