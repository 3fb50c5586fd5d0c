// `marchstudio test SUITE.toml`: image, cost and frame-time tests of a
// user's own scenes and shaders, in one process (suite/suite*.h), with a
// line per case on the terminal and JUnit XML, JSON and an HTML report for
// CI. docs/testing.md.
#pragma once
#include <string>
#include <vector>

#include "suite/outcome.h"
#include "render/compute_frame.h"

namespace CLI {
class App;
}

namespace ms {

struct TestArgs {
  std::string suite;
  std::string junit;                  // JUnit XML file; empty: none
  std::string report;                 // HTML report directory; empty: none
  bool json = false;                  // the results as JSON on stdout (the case lines go to stderr)
  bool update = false;                // write missing and failing references
  bool force = false;                 // --update even with CI set
  ExitCodes exit_codes = ExitCodes::standard;  // --exit-codes default | idiff
  std::vector<std::string> only;      // case-name globs
  bool list = false;                  // print the cases and exit
  bool verbose = false;               // -v: every compile error of a case that could not run
  std::string shader_dir;
  Dispatch dispatch = Dispatch::fragment;  // --dispatch fragment|compute (cli/dispatch_flag.h)
};

CLI::App* add_test_command(CLI::App& app, TestArgs& args);
int run_test(const TestArgs& args);

}  // namespace ms
