// A JSON text parsed into one flat array of values, each knowing its line,
// its parent and its key, so a reader can name any value's line and JSON
// pointer in an error. Parsed with an explicit stack into storage sized by
// a first pass over the text and checked against the memory budget before
// it is allocated: a chain nested 100,000 deep costs no recursion, and a
// file of a million '[' is refused by name, not swapped for.
//
//   const JsonDoc doc = parse_json_doc(text, "molecule.json");  // throws ms::Error, one line
//   const JsonValue& root = doc.at(0);
//   for (int c = root.first; c != -1; c = doc.at(c).next) ...  // members or elements in order
//   doc.key(c), doc.text(c)  // a member's name, a string's value
//   doc.pointer(i)  // "/root/children/3/sdf"
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

enum class JsonKind : std::uint8_t { null, boolean, number, string, array, object };

// 56 bytes: strings live in JsonDoc::strings, so a value of any kind costs
// the same and an empty one nothing more.
struct JsonValue {
  int line = 0;         // where the value starts, from 1
  int parent = -1;      // -1 for the document's value
  int first = -1;       // first member or element, -1 when none
  int next = -1;        // the next sibling, -1 when last
  int count = 0;        // members or elements
  int index = 0;        // position in the parent array (arrays only)
  double number = 0.0;  // numbers; booleans as 0 / 1
  std::uint32_t text_at = 0, text_size = 0;  // a string's value in JsonDoc::strings
  std::uint32_t key_at = 0, key_size = 0;    // the member name when the parent is an object
  JsonKind kind = JsonKind::null;
};

struct JsonDoc {
  std::vector<JsonValue> values;  // values[0] is the document's value
  std::string strings;            // every string value and member name, end to end
  const JsonValue& at(int i) const { return values[static_cast<std::size_t>(i)]; }
  std::string_view text(int i) const { return {strings.data() + at(i).text_at, at(i).text_size}; }
  std::string_view key(int i) const { return {strings.data() + at(i).key_at, at(i).key_size}; }
  // Stores `s` as v's string value or member name.
  void set_text(JsonValue& v, std::string_view s);
  void set_key(JsonValue& v, std::string_view s);
  // The member named `key` of object `obj`, or -1.
  int member(int obj, std::string_view key) const;
  // RFC 6901 pointer of value i: "" for the root, "/a/0/b" below it. For
  // error lines: each name cut as quote() cuts it, and a pointer of more
  // than 13 steps shown as its first 4 and last 8 around "/...".
  std::string pointer(int i) const;
};

// What a caller keeps beyond the document while it reads one, in bytes per
// value and per level of nesting (a graph's nodes and its builder's stack),
// so that the check before parsing covers the whole read.
struct JsonCost {
  std::size_t per_value = 0;
  std::size_t per_level = 0;
};

// True when `text` looks like JSON (its first non-space byte is '{' or
// '['): a .json input, or a .glsl that is really a Shadertoy download.
bool looks_like_json(std::string_view text);

// Throws ms::Error (exit 2) naming `display`, the line and what is wrong:
// malformed text, a duplicate key, a number that is not finite; and, before
// anything is allocated, a text whose values and nesting with `extra` need
// more than `budget` bytes (0: core/memory_budget.h's).
JsonDoc parse_json_doc(std::string_view text, const std::string& display, JsonCost extra = {}, double budget = 0);

}  // namespace ms
