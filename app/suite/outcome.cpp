#include "suite/outcome.h"

#include <cmath>

namespace ms {

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::pass: return "pass";
    case Outcome::warn: return "warn";
    case Outcome::fail: return "fail";
    case Outcome::error: return "error";
  }
  return "?";
}

ExitCodes parse_exit_codes(const std::string& name) {
  if (name == "default") return ExitCodes::standard;
  if (name == "idiff") return ExitCodes::idiff;
  fail_input("unknown exit-code convention '" + name + "'", {}, 0, "--exit-codes",
             "use default (0 pass, 1 fail, 2 bad input, 3 system) or idiff (0 pass, 1 warn, 2 fail, 4 could not run)");
}

int exit_code_for(ExitCodes codes, Outcome worst, Exit error_code) {
  if (codes == ExitCodes::idiff) {
    switch (worst) {
      case Outcome::pass: return 0;
      case Outcome::warn: return 1;
      case Outcome::fail: return 2;
      case Outcome::error: return 4;
    }
  }
  switch (worst) {
    case Outcome::pass:
    case Outcome::warn: return static_cast<int>(Exit::ok);
    case Outcome::fail: return static_cast<int>(Exit::threshold);
    case Outcome::error: return static_cast<int>(error_code == Exit::system ? Exit::system : Exit::bad_input);
  }
  return static_cast<int>(Exit::system);
}

Outcome classify(const CompareMetrics& m, Metric metric, double threshold, std::optional<double> warn) {
  if (!within_threshold(m, metric, threshold)) return Outcome::fail;
  if (warn && !within_threshold(m, metric, *warn)) return Outcome::warn;
  return Outcome::pass;
}

bool warn_level_valid(Metric metric, double threshold, double warn) {
  if (std::isnan(warn)) return false;
  return metric == Metric::psnr ? warn >= threshold : warn <= threshold;
}

}  // namespace ms
