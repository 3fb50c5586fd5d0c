#include "core/error.h"

#include <sstream>

namespace ms {

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
  return out.str();
}

Error::Error(ErrorInfo info) : std::runtime_error(format_error(info)), info_(std::move(info)) {}

void fail_input(std::string what, std::string file, int line, std::string key, std::string hint) {
  throw Error({Exit::bad_input, std::move(file), line, std::move(key), std::move(what), std::move(hint)});
}

void fail_system(std::string what, std::string file) {
  throw Error({Exit::system, std::move(file), 0, {}, std::move(what), {}});
}

}  // namespace ms
