// File watching with inotify for hot reload. Files are watched through their
// DIRECTORIES and events are filtered by file name: editors that save by
// writing a temporary and renaming it over the original (vim, VS Code) would
// otherwise leave a watch on a deleted inode. No threads: the caller polls
// (the viewer, once per frame) or waits (render --watch) on fd().
#pragma once
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ms::live {

class Watcher {
 public:
  // Throws Exit::system when inotify is unavailable.
  Watcher();
  ~Watcher();
  Watcher(const Watcher&) = delete;
  Watcher& operator=(const Watcher&) = delete;

  // Replace the watched set (absolute or relative paths; made absolute).
  // Directories no longer needed are unwatched, new ones watched; a
  // directory that does not exist (yet) is retried on the next call.
  void watch(const std::vector<std::filesystem::path>& files);
  // While set, an event on any file in a watched directory with the same
  // extension as a watched file counts: after a failed reload the fix may be
  // a file that nothing includes yet.
  void set_match_any(bool on) { match_any_ = on; }

  // Drain pending events without blocking: the watched files that were
  // written, created, renamed onto, deleted or moved away; sorted, unique.
  std::vector<std::filesystem::path> poll();
  // Block up to timeout_ms (< 0: forever) for a first relevant change, then
  // keep collecting until no event came for quiet_ms (debounce: one reload
  // per save, even when an editor writes in several steps), but at most
  // max_settle_ms. Returns the changed files (empty on timeout).
  std::vector<std::filesystem::path> wait(int timeout_ms, int quiet_ms, int max_settle_ms);
  // After poll() found changes: the same settling as wait().
  void settle(std::vector<std::filesystem::path>& changed, int quiet_ms, int max_settle_ms);

  int fd() const { return fd_; }
  const std::vector<std::filesystem::path>& files() const { return files_; }
  std::vector<std::filesystem::path> directories() const;

 private:
  void read_events(std::set<std::filesystem::path>& out);

  int fd_ = -1;
  bool match_any_ = false;
  std::vector<std::filesystem::path> files_;
  std::set<std::string> extensions_;  // of files_, for match-any
  std::map<int, std::filesystem::path> dir_of_wd_;           // watch descriptor -> directory
  std::map<std::filesystem::path, std::set<std::string>> names_;  // directory -> file names of interest
};

}  // namespace ms::live
