// sweep's outputs: CSV (one line per row), JSON (schema
// "marchstudio.sweep/1", with the machine and the reference settings) and
// a table for people. Field meanings: docs/speed-vs-error.md.
#pragma once
#include <string>

#include "sweep/sweep.h"

namespace ms {

inline constexpr const char* kSweepSchema = "marchstudio.sweep/1";

struct SweepSubject {
  std::string scene_file;  // as given
  std::string scene_name;
  std::string command;     // the command line that made it, for the record
  std::string specialize;  // "folded" (as render and bench build it) or "generic"
};

// Header line plus one line per row, each ending in a newline. Infinite
// PSNR is written "inf"; figures that do not apply are left empty.
std::string sweep_csv(const SweepResult& r);

// The whole sweep as one pretty-printed JSON object ending in a newline.
// Infinite PSNR and figures that do not apply are null.
std::string sweep_json(const SweepSubject& subject, const SweepSettings& s, const SweepResult& r);

// A fixed-width table, ending in a newline.
std::string sweep_table(const SweepSubject& subject, const SweepSettings& s, const SweepResult& r);

}  // namespace ms
