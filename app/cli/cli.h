// Command-line entry: parses argv with CLI11, dispatches a subcommand, and
// turns every ms::Error into one line on stderr plus its exit code.
#pragma once

namespace ms {

int run_cli(int argc, char** argv);

// Flushes stdout and stderr and returns `code`, or Exit::system when a
// write to either failed (a full disk, `> /dev/full`) and `code` said all
// was well (0) or only a threshold failed (1): the output is lost, and the
// exit code must not say otherwise.
int finish_output(int code);

}  // namespace ms
