// A JSON text parsed into one flat array of values, each knowing its line,
// its parent and its key, so a reader can name any value's line and JSON
// pointer in an error. Parsed with an explicit stack and freed as one
// vector: a chain nested 100,000 deep costs no recursion and no stack.
//
//   const JsonDoc doc = parse_json_doc(text, "molecule.json");  // throws ms::Error, one line
//   const JsonValue& root = doc.at(0);
//   for (int c = root.first; c != -1; c = doc.at(c).next) ...  // members or elements in order
//   doc.pointer(i)  // "/root/children/3/sdf"
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

enum class JsonKind : std::uint8_t { null, boolean, number, string, array, object };

struct JsonValue {
  JsonKind kind = JsonKind::null;
  int line = 0;         // where the value starts, from 1
  int parent = -1;      // -1 for the document's value
  int first = -1;       // first member or element, -1 when none
  int next = -1;        // the next sibling, -1 when last
  int count = 0;        // members or elements
  int index = 0;        // position in the parent array (arrays only)
  double number = 0.0;  // numbers; booleans as 0 / 1
  std::string text;     // strings' value
  std::string key;      // the member name when the parent is an object
};

struct JsonDoc {
  std::vector<JsonValue> values;  // values[0] is the document's value
  const JsonValue& at(int i) const { return values[static_cast<std::size_t>(i)]; }
  // The member named `key` of object `obj`, or -1.
  int member(int obj, std::string_view key) const;
  // RFC 6901 pointer of value i: "" for the root, "/a/0/b" below it.
  std::string pointer(int i) const;
};

// Throws ms::Error (exit 2) naming `display`, the line and what is wrong:
// malformed text, a duplicate key, a number that is not finite.
JsonDoc parse_json_doc(std::string_view text, const std::string& display);

}  // namespace ms
