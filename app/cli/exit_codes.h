// `--exit-codes idiff` for commands that check things (compare, test):
// under idiff's convention whatever keeps the check from running exits 4,
// where every other command's errors exit 2 or 3 (cli.cpp).
#pragma once
#include <functional>

#include "suite/outcome.h"

namespace ms {

// Runs `command`; with idiff codes an ms::Error is printed as one line and
// becomes 4, otherwise it propagates to cli.cpp as usual.
int run_with_exit_codes(ExitCodes codes, const std::function<int()>& command);

}  // namespace ms
