// Runs the real marchstudio binary for integration tests and captures its
// exit code, stdout and stderr. Compiled into the CLI tests only: it needs
// MARCH_BIN, the binary's path.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include "files.h"

namespace ms::test {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Arguments are shell-quoted; the working directory is `cwd` when given.
// `shell_prefix` runs in the same sh first, e.g. "ulimit -s 1024; ".
RunResult run_marchstudio(const std::vector<std::string>& args, const std::filesystem::path& cwd = {},
                          const std::string& shell_prefix = {});

// A `shell_prefix` that caps the run's address space at `kib` KiB, for
// tests that a run stays small; empty under ASan, which reserves terabytes
// of shadow memory and so cannot run under any cap.
inline std::string address_space_limit(long kib) {
#if defined(__SANITIZE_ADDRESS__)
  (void)kib;
  return {};
#else
  return "ulimit -v " + std::to_string(kib) + "; ";
#endif
}

// Starts marchstudio in the background in `dir`, stdout and stderr to the
// file `log` (relative to `dir`); the caller waits for or kills the pid.
pid_t spawn_marchstudio(const std::vector<std::string>& args, const std::filesystem::path& dir, const std::string& log);

// Finished files in `dir` whose names start with `prefix` (temporaries,
// named *.tmp*, left out).
int count_files(const std::filesystem::path& dir, const std::string& prefix);
// Polls until `dir` holds `n` such files: a fatal test failure when `pid`
// ends first (with `log`, a file under `dir`, in the message) or after 120 s.
void wait_for_files(const std::filesystem::path& dir, const std::string& prefix, int n, pid_t pid,
                    const std::string& log = {});

}  // namespace ms::test
