// Text that leaves marchstudio (error lines, JSON and JUnit reports, the
// HTML report) is valid UTF-8. Much of it is echoed from elsewhere: a
// driver's compile log quoting a shader's bytes, a file name, a suite's
// strings. One byte that is not UTF-8 would make a JSON writer throw or an
// XML parser refuse the whole report, so such bytes become U+FFFD.
//
//   std::string shown = valid_utf8(driver_log);
//
// Header-only: the image module (io/oiio/) carries its own copy of the core
// files it uses, and needs no new one for this.
#pragma once
#include <string>
#include <string_view>

namespace ms {

// The length of the well-formed UTF-8 sequence at s[i], or 0 when the
// byte there does not start one (overlong forms, surrogates and code
// points past U+10FFFF are not well-formed).
inline std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = at(i);
  if (c < 0x80) return 1;
  std::size_t n;
  unsigned char lo = 0x80, hi = 0xbf;  // the range of the second byte
  if (c >= 0xc2 && c <= 0xdf) n = 2;
  else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    if (c == 0xe0) lo = 0xa0;       // overlong
    if (c == 0xed) hi = 0x9f;       // surrogates
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    if (c == 0xf0) lo = 0x90;       // overlong
    if (c == 0xf4) hi = 0x8f;       // past U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return n;
}

inline bool is_valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

// `s` with every byte that is not part of a well-formed sequence replaced
// by U+FFFD; valid text comes back unchanged.
inline std::string valid_utf8(std::string_view s) {
  if (is_valid_utf8(s)) return std::string(s);
  std::string out;
  out.reserve(s.size() + 8);
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) {
      out += "\xef\xbf\xbd";
      ++i;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  return out;
}

}  // namespace ms
