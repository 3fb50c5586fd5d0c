// marchstudio: one program, subcommands dispatched by cli/, on a thread
// whose stack a deep shader compile cannot overflow (core/big_stack.h).
#include <csignal>

#include "cli/cli.h"
#include "core/big_stack.h"

int main(int argc, char** argv) {
  // A file size limit (ulimit -f) then fails the write, which io/atomic_file.h
  // reports as it reports a full disk, instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  return ms::run_on_big_stack([&] { return ms::run_cli(argc, argv); });
}
