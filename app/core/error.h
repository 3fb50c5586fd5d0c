// The one error type: what went wrong, where (file:line, key), and a hint.
// Thrown by every module; main() prints it as a single line and exits with
// its code.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace ms {

// Process exit codes (docs/usage.md documents them).
enum class Exit : int {
  ok = 0,
  threshold = 1,  // a comparison or budget over its threshold
  bad_input = 2,  // scene, shader, flags, paths
  system = 3,     // no GL context, out of memory, I/O
};

struct ErrorInfo {
  Exit code = Exit::bad_input;
  std::string file;  // empty when the error has no file
  int line = 0;      // 0 when unknown
  std::string key;   // dotted TOML key or flag name, empty when none
  std::string what;  // the message, without file/line
  std::string hint;  // e.g. "did you mean 'light'?", empty when none
  // More than the line holds, printed after it with -v: a compile error's
  // whole driver log, each location mapped to file:line. Empty when none.
  std::string detail;
};

class Error : public std::runtime_error {
 public:
  explicit Error(ErrorInfo info);
  const ErrorInfo& info() const { return info_; }
  Exit code() const { return info_.code; }

 private:
  ErrorInfo info_;
};

// The hint's words for the rest of a compile log (ErrorInfo::detail): the
// command line prints the log under -v; the viewer shows it anyway and says
// so in their place (live/session.h).
inline constexpr std::string_view kVerboseHint = "-v prints them all";

// "file:line: what (hint)", the line printed after "marchstudio: ".
std::string format_error(const ErrorInfo& info);

// Shorthands for the common cases.
[[noreturn]] void fail_input(std::string what, std::string file = {}, int line = 0,
                             std::string key = {}, std::string hint = {});
[[noreturn]] void fail_system(std::string what, std::string file = {});

}  // namespace ms
