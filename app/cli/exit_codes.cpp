#include "cli/exit_codes.h"

#include <cstdio>

#include "core/error.h"

namespace ms {

int run_with_exit_codes(ExitCodes codes, const std::function<int()>& command) {
  try {
    return command();
  } catch (const Error& e) {
    if (codes != ExitCodes::idiff) throw;
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    return exit_code_for(codes, Outcome::error);
  }
}

}  // namespace ms
