// Tests that must hold for both dispatches of the scene pass (the
// fragment pass and the compute dispatch, --dispatch) are written once
// and run for each, as fidget runs its evaluator tests for VM and JIT:
//
//   class NanGuard : public BothDispatches {};
//   TEST_P(NanGuard, StrictWritesNothing) {
//     const RunResult r = run_marchstudio(with_dispatch({"render", scene, "--strict"}));
//     ...
//   }
//   INSTANTIATE_BOTH_DISPATCHES(NanGuard);   // NanGuard.StrictWritesNothing/fragment, /compute
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ms::test {

class BothDispatches : public ::testing::TestWithParam<const char*> {
 protected:
  // The dispatch this run tests: "fragment" or "compute".
  std::string dispatch() const { return GetParam(); }
  // A command line with --dispatch added.
  std::vector<std::string> with_dispatch(std::vector<std::string> args) const {
    args.push_back("--dispatch");
    args.push_back(GetParam());
    return args;
  }
};

}  // namespace ms::test

#define INSTANTIATE_BOTH_DISPATCHES(Suite)                                                          \
  INSTANTIATE_TEST_SUITE_P(, Suite, ::testing::Values("fragment", "compute"),                        \
                           [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); })
