// Numbers and quoted text in messages, reports and TOML writeback, one way
// everywhere.
//
//   format_number(1e-4)              -> "0.0001"   (%g)
//   printf_number("%.2f dB", 41.234) -> "41.23 dB"
//   quote(key)                       -> "'fov'", cut with "..." past 64 bytes
#pragma once
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

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

// A key or value fit for a one-line message: control characters escaped,
// long text cut, so a hostile file cannot break the error line.
inline std::string printable(std::string_view text, std::size_t max_bytes = 64) {
  std::size_t cut = text.size();
  if (cut > max_bytes) {
    cut = max_bytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8 boundary
  }
  std::string out;
  for (char c : text.substr(0, cut)) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", u);
      out += buf;
    } else out += c;
  }
  if (cut < text.size()) out += "...";
  return out;
}

// printable(text) in single quotes: 'fov'. Appends rather than
// "'" + std::string: GCC 12 warns falsely (-Wrestrict) on that.
inline std::string quote(std::string_view text) {
  std::string out(1, '\'');
  out += printable(text);
  out += '\'';
  return out;
}

}  // namespace ms
