// `marchstudio compare A B`: image metrics of B against the reference A,
// with a threshold on one of them deciding the exit code (0 within, 1 over),
// so it drops straight into CI. Metrics live in bench/compare.h.
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace ms {

struct CompareArgs {
  std::string a;                  // the reference (a golden)
  std::string b;                  // the candidate
  std::string metric = "psnr";    // psnr | mae | max | fraction
  double threshold = 0.0;         // meaningful only when threshold_set
  bool threshold_set = false;     // unset: exact match required
  double pixel_threshold = 1.0 / 255.0;
  std::string diff;               // heat map output; empty: none written
  bool json = false;
};

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);
int run_compare(const CompareArgs& args);

}  // namespace ms
