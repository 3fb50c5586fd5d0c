// A JSON value as an error message may quote it: a string or a number as
// written, an array or object by kind and size only. Never recursive and
// never long, so a hostile value (a million nested arrays, a megabyte
// string) still gives a one-line error.
//
//   fail_input("not a JSON object: " + json_brief(value), ...);
#pragma once
#include <nlohmann/json.hpp>

#include <string>

namespace ms {

inline std::string json_brief(const nlohmann::json& v, size_t max_chars = 60) {
  std::string text;
  if (v.is_array()) text = "an array of " + std::to_string(v.size());
  else if (v.is_object()) text = "an object of " + std::to_string(v.size()) + " keys";
  else text = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > max_chars) text = text.substr(0, max_chars) + "...";
  return text;
}

}  // namespace ms
