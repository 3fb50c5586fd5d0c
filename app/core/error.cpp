#include "core/error.h"

#include <sstream>

#include "core/utf8.h"

namespace ms {

namespace {

// An error is one line: a newline or another control character in a file
// name (or echoed text) is shown escaped, as \n or \x1b; bytes that are
// not UTF-8 become U+FFFD (core/utf8.h).
std::string one_line(const std::string& s) {
  std::string out;
  for (unsigned char c : valid_utf8(s)) {
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

}  // namespace

// (An ostringstream rather than string +=: GCC 12 warns falsely on the latter, PR105651.)
std::string format_error(const ErrorInfo& e) {
  std::ostringstream out;
  if (!e.file.empty()) {
    out << e.file;
    if (e.line > 0) out << ':' << e.line;
    out << ": ";
  }
  // Name the key unless the message already does (scene errors quote it).
  if (!e.key.empty() && e.what.find(e.key) == std::string::npos) out << e.key << ": ";
  out << e.what;
  if (!e.hint.empty()) out << " (" << e.hint << ')';
  return one_line(out.str());
}

Error::Error(ErrorInfo info) : std::runtime_error(format_error(info)), info_(std::move(info)) {}

void fail_input(std::string what, std::string file, int line, std::string key, std::string hint) {
  throw Error({Exit::bad_input, std::move(file), line, std::move(key), std::move(what), std::move(hint), {}});
}

void fail_system(std::string what, std::string file) {
  throw Error({Exit::system, std::move(file), 0, {}, std::move(what), {}, {}});
}

}  // namespace ms
