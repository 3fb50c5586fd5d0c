#include "live/watcher.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/clock.h"
#include "core/error.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

// Everything a save can look like: in-place write (CLOSE_WRITE, MODIFY),
// rename over (MOVED_TO), delete + create (vim's backup dance), deletion.
constexpr uint32_t kMask = IN_CLOSE_WRITE | IN_MODIFY | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE |
                           IN_ATTRIB | IN_DELETE_SELF | IN_MOVE_SELF;

fs::path absolute_normal(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

long long now_ms() { return static_cast<long long>(clock_seconds() * 1e3); }

bool wait_readable(int fd, int timeout_ms) {
  pollfd p{fd, POLLIN, 0};
  for (;;) {
    const int r = ::poll(&p, 1, timeout_ms);
    if (r < 0 && errno == EINTR) continue;
    return r > 0;
  }
}

}  // namespace

Watcher::Watcher() {
  fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) fail_system(std::string("inotify_init1: ") + std::strerror(errno));
}

Watcher::~Watcher() {
  if (fd_ >= 0) ::close(fd_);
}

void Watcher::watch(const std::vector<fs::path>& files) {
  std::map<fs::path, std::set<std::string>> names;
  files_.clear();
  extensions_.clear();
  for (const fs::path& f : files) {
    const fs::path a = absolute_normal(f);
    if (a.filename().empty()) continue;
    if (names[a.parent_path()].insert(a.filename().string()).second) files_.push_back(a);
    if (a.has_extension()) extensions_.insert(a.extension().string());
  }
  // Drop directories nobody needs any more.
  for (auto it = dir_of_wd_.begin(); it != dir_of_wd_.end();) {
    if (!names.count(it->second)) {
      inotify_rm_watch(fd_, it->first);
      it = dir_of_wd_.erase(it);
    } else {
      ++it;
    }
  }
  // Add the new ones (inotify_add_watch on a watched dir returns its wd).
  for (const auto& [dir, n] : names) {
    const int wd = inotify_add_watch(fd_, dir.c_str(), kMask);
    if (wd >= 0) dir_of_wd_[wd] = dir;  // a missing directory is retried next time
  }
  names_ = std::move(names);
}

std::vector<fs::path> Watcher::directories() const {
  std::vector<fs::path> out;
  for (const auto& [wd, dir] : dir_of_wd_) out.push_back(dir);
  return out;
}

void Watcher::read_events(std::set<fs::path>& out) {
  alignas(inotify_event) char buf[16384];
  for (;;) {
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) continue;
      return;  // EAGAIN: drained
    }
    for (ssize_t off = 0; off < n;) {
      const auto* ev = reinterpret_cast<const inotify_event*>(buf + off);
      off += static_cast<ssize_t>(sizeof(inotify_event) + ev->len);
      if (ev->mask & IN_Q_OVERFLOW) {  // events were lost (a save storm): assume everything changed
        out.insert(files_.begin(), files_.end());
        continue;
      }
      auto it = dir_of_wd_.find(ev->wd);
      if (it == dir_of_wd_.end()) continue;
      if (ev->mask & IN_IGNORED) {  // the directory itself went away
        dir_of_wd_.erase(it);
        continue;
      }
      if (ev->len == 0) continue;  // an event on the directory, not a file in it
      const std::string name = ev->name;
      const auto names = names_.find(it->second);
      const bool wanted = names != names_.end() && names->second.count(name);
      // Match-any still wants a source-like name: the same extension as a
      // watched file, so screenshots or an editor's swap files written next
      // to the scene do not trigger reloads.
      const bool any = match_any_ && !(ev->mask & IN_ISDIR) && extensions_.count(fs::path(name).extension().string());
      if (wanted || any) out.insert(it->second / name);
    }
  }
}

std::vector<fs::path> Watcher::poll() {
  std::set<fs::path> changed;
  read_events(changed);
  return {changed.begin(), changed.end()};
}

void Watcher::settle(std::vector<fs::path>& changed, int quiet_ms, int max_settle_ms) {
  std::set<fs::path> all(changed.begin(), changed.end());
  const long long deadline = now_ms() + max_settle_ms;
  for (;;) {
    const long long left = deadline - now_ms();
    if (left <= 0) break;
    if (!wait_readable(fd_, static_cast<int>(std::min<long long>(quiet_ms, left)))) break;  // quiet: done
    read_events(all);
  }
  changed.assign(all.begin(), all.end());
}

std::vector<fs::path> Watcher::wait(int timeout_ms, int quiet_ms, int max_settle_ms) {
  const long long deadline = timeout_ms < 0 ? -1 : now_ms() + timeout_ms;
  std::vector<fs::path> changed;
  for (;;) {
    int left = -1;
    if (deadline >= 0) {
      left = static_cast<int>(std::max<long long>(0, deadline - now_ms()));
    }
    if (!wait_readable(fd_, left)) return {};
    changed = poll();
    if (!changed.empty()) break;
    if (deadline >= 0 && now_ms() >= deadline) return {};
  }
  settle(changed, quiet_ms, max_settle_ms);
  return changed;
}

}  // namespace ms::live
