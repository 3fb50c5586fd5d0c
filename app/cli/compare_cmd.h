// `marchstudio compare A B`: image metrics of B against the reference A,
// with a threshold on one of them deciding the exit code (0 within, 1 over;
// or idiff's 0 pass, 1 warn, 2 fail, 4 could not run), so it drops straight
// into CI. Metrics live in io/compare.h.
#pragma once
#include <string>

#include "io/compare.h"
#include "suite/outcome.h"

namespace CLI {
class App;
}

namespace ms {

struct CompareArgs {
  std::string a;                  // the reference (a golden)
  std::string b;                  // the candidate
  Metric metric = Metric::psnr;   // --metric psnr | mae | max | fraction | flip, parsed as read
  double threshold = 0.0;         // meaningful only when threshold_set
  bool threshold_set = false;     // unset: exact match required
  double pixel_threshold = 1.0 / 255.0;
  double warn = 0.0;              // meaningful only when warn_set: pass, but worse than this, warns
  bool warn_set = false;
  std::string diff;               // heat map output; empty: none written
  bool json = false;
  ExitCodes exit_codes = ExitCodes::standard;  // --exit-codes default | idiff (suite/outcome.h)
};

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);
int run_compare(const CompareArgs& args);

}  // namespace ms
