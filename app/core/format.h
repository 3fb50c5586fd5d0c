// Numbers in messages, reports and TOML writeback, one way everywhere.
//
//   format_number(1e-4)              -> "0.0001"   (%g)
//   printf_number("%.2f dB", 41.234) -> "41.23 dB"
#pragma once
#include <cstdio>
#include <string>

namespace ms {

// printf of one double; `format` holds exactly one conversion and the text
// is cut at 63 bytes.
inline std::string printf_number(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A number as %g: "0.0001", "1e+20", "nan".
inline std::string format_number(double v) { return printf_number("%g", v); }

}  // namespace ms
