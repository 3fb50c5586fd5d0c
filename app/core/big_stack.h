// Runs a function on a thread with a large, explicit stack.
//
//   int rc = ms::run_on_big_stack([&] { return run_cli(argc, argv); });
//
// Why: Mesa's GLSL compiler recurses once per level of an expression's
// syntax tree (426-686 bytes a level, measured by bisecting `ulimit -s`;
// tests/cli/test_attacks_input.cpp), so
// a 20,000-term sum overflowed the 8 MiB main-thread stack and killed the
// process with SIGSEGV. A thread's stack size is set here, independent of
// `ulimit -s`; the memory is reserved, not used, until a deep compile
// touches it. preprocess/macro_engine.h refuses expressions deeper than what
// this stack holds with room to spare (max_expression_depth, 50,000 levels:
// at most about 34 MiB of the 256 MiB).
#pragma once
#include <cstddef>
#include <functional>

namespace ms {

// The compile stack: every subcommand runs on it, the viewer included.
inline constexpr std::size_t kBigStackBytes = std::size_t{256} << 20;

// Calls fn() on a new thread with `bytes` of stack and returns its result.
// Exceptions propagate. Where the thread cannot be made (an address-space
// limit, `ulimit -v`), smaller stacks are tried, and last fn() runs here.
int run_on_big_stack(const std::function<int()>& fn, std::size_t bytes = kBigStackBytes);

}  // namespace ms
