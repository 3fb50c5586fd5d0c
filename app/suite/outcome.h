// How a check ended, and the exit code a run of checks returns: `compare`
// and `test` share both. Two conventions (docs/usage.md, docs/testing.md):
//   default: 0 all pass (warnings included), 1 some fail, 2 bad input, 3 system
//   idiff:   0 pass, 1 warn, 2 fail, 4 could not run (OpenImageIO's idiff)
#pragma once
#include <optional>
#include <string>

#include "io/compare.h"
#include "core/error.h"

namespace ms {

// Ordered: a run's outcome is its worst check's.
enum class Outcome { pass, warn, fail, error };  // error: the check could not run
const char* outcome_name(Outcome o);              // "pass", "warn", "fail", "error"

enum class ExitCodes { standard, idiff };
// "default" | "idiff"; throws bad_input (key --exit-codes) otherwise.
ExitCodes parse_exit_codes(const std::string& name);

// The process exit code for a run whose worst outcome is `worst`. With
// standard codes an error exits with `error_code` (bad_input or system).
int exit_code_for(ExitCodes codes, Outcome worst, Exit error_code = Exit::bad_input);

// A metric against its threshold and optional warn level. psnr fails below
// the threshold and warns below `warn`; mae, max and fraction fail above
// the threshold and warn above `warn`. Boundary values pass. NaN/Inf in
// either image always fail.
Outcome classify(const CompareMetrics& m, Metric metric, double threshold, std::optional<double> warn = {});

// Whether `warn` lies on the passing side of `threshold` (or on it): a warn
// level that cannot be reached before failing is a mistake.
bool warn_level_valid(Metric metric, double threshold, double warn);

}  // namespace ms
