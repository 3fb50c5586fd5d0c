// bench's two outputs: one JSON object (schema "marchstudio.bench/1",
// documented field by field in docs/bench.md) and a table for people.
#pragma once
#include <string>
#include <vector>

#include "bench/bench.h"

namespace ms {

inline constexpr const char* kBenchSchema = "marchstudio.bench/1";

// What was benchmarked, as the user asked for it.
struct BenchSubject {
  std::string scene_file;            // as given on the command line
  std::string scene_name;
  std::vector<std::string> disable;  // effects switched off
  std::string specialize = "folded"; // the scene shader: "folded" (specialized) or "generic" (--no-specialize)
  std::vector<std::string> overrides;  // --set and --uniform flags as given, in order
};

// The JSON document, pretty-printed, ending in a newline.
std::string bench_json(const BenchSubject& subject, const BenchSettings& s, const BenchResult& r);

// The human-readable report, ending in a newline.
std::string bench_table(const BenchSubject& subject, const BenchSettings& s, const BenchResult& r);

}  // namespace ms
