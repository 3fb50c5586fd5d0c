// Command-line entry: parses argv with CLI11, dispatches a subcommand, and
// turns every ms::Error into one line on stderr plus its exit code.
#pragma once

namespace ms {

int run_cli(int argc, char** argv);

}  // namespace ms
