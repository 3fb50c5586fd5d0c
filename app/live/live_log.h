// The viewer's machine-readable log: one line per event ("reload ok 3
// frames=1 ..."), to --log FILE or, without it, to stderr. Tests and
// scripts read it; docs/viewer.md lists the lines.
#pragma once
#include <cstdio>
#include <filesystem>
#include <string>

namespace ms::live {

class LiveLog {
 public:
  // Empty path: stderr. Throws bad_input when the file cannot be created.
  explicit LiveLog(const std::filesystem::path& file);
  ~LiveLog();
  LiveLog(const LiveLog&) = delete;
  LiveLog& operator=(const LiveLog&) = delete;

  // Writes `text` and a newline, flushed at once (a reader may be waiting).
  void line(const std::string& text);
  bool to_stderr() const { return file_ == stderr; }

 private:
  std::FILE* file_ = stderr;
};

}  // namespace ms::live
