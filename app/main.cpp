// marchstudio: one program, subcommands dispatched by cli/, on a thread
// whose stack a deep shader compile cannot overflow (core/big_stack.h).
#include "cli/cli.h"
#include "core/big_stack.h"

int main(int argc, char** argv) {
  return ms::run_on_big_stack([&] { return ms::run_cli(argc, argv); });
}
