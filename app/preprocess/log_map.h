// Driver info logs -> "file:line: severity: message", using the source-string
// table that preprocess() built. No GL here: the caller passes the log text.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "preprocess/preprocess.h"

namespace ms {

struct ShaderDiagnostic {
  std::string file;      // display path; empty when the log line had no location we understand
  int line = 0;          // 0 when unknown
  std::string severity;  // "error", "warning", "info", or empty for lines passed through
  std::string message;
  std::string suggestion;  // "did you mean 'MAT_BALL'?" for an unknown name, or empty
};

struct SourceLocation {
  std::string file;  // display path; empty when the location is not one preprocess() emitted
  int line = 0;
};

// A driver-reported (source string, line) as file:line. Decodes the
// kLineStride line encoding, so it is right even where the driver reports
// string 0 for everything (Mesa does for all errors past the parser).
SourceLocation map_location(const ShaderSource& src, long long string_no, long long line);

// Understands Mesa `0:12(5): error: ...`, NVIDIA `0(12) : error C0000: ...`
// and glslang-style `ERROR: 0:12: ...` (also used by AMD, Intel on Windows
// and Apple), plus location-less `error: ...` / `ERROR: ...` link messages.
// Lines in any other format pass through with an empty file; blank lines and
// glslang's "N compilation errors" summary are dropped.
std::vector<ShaderDiagnostic> parse_info_log(std::string_view log, const ShaderSource& src);

// For each diagnostic about an unknown name (an undeclared identifier, no
// function of that name), the nearest name `program` defines (its #define
// macros, MAT_<NAME> included, and its functions) or a GLSL built-in.
void suggest_names(std::vector<ShaderDiagnostic>& diags, std::string_view program);

// One "file:line: severity: message (suggestion)" line per diagnostic, each
// ending in '\n'.
std::string format_diagnostics(const std::vector<ShaderDiagnostic>& diags);

}  // namespace ms
