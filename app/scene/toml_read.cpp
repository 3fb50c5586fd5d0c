#include "scene/toml_read.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/suggest.h"

namespace ms {

namespace {

std::string num(double v) { return format_number(v); }

// "a string", "an integer", ... for "must be X, not Y" messages.
std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

}  // namespace

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return "in " + std::string(lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + (hi_open ? ")" : "]");
  if (has_lo) return (lo_open ? "> " : ">= ") + num(lo);
  if (has_hi) return (hi_open ? "< " : "<= ") + num(hi);
  return "a number";
}

std::string join_key(std::string_view path, std::string_view key) {
  return path.empty() ? std::string(key) : std::string(path) + "." + std::string(key);
}

void Reader::fail(int line, std::string_view key, std::string what, std::string hint) const {
  fail_input(std::move(what), file_, line, printable(key), std::move(hint));
}

void Reader::fail(const toml::node& at, std::string_view key, std::string what, std::string hint) const {
  fail(static_cast<int>(at.source().begin.line), key, std::move(what), std::move(hint));
}

int Reader::line_of(const toml::table& t, std::string_view key) {
  if (const toml::node* n = key.empty() ? nullptr : t.get(key))
    return static_cast<int>(n->source().begin.line);
  return static_cast<int>(t.source().begin.line);
}

void Reader::check_keys(const toml::table& t, std::string_view path, Keys known,
                        const std::function<std::string(std::string_view)>& elsewhere) const {
  for (auto&& [k, v] : t) {
    if (std::find(known.begin(), known.end(), k.str()) != known.end()) continue;
    const std::string full = join_key(path, k.str());
    std::string hint = did_you_mean(k.str(), known);
    if (hint.empty() && elsewhere) hint = elsewhere(k.str());
    fail(static_cast<int>(k.source().begin.line), full, "unknown key " + quote(full), std::move(hint));
  }
}

const toml::table* Reader::table(const toml::table& t, std::string_view path, std::string_view key) const {
  const toml::node* n = t.get(key);
  if (!n) return nullptr;
  const std::string full = join_key(path, key);
  if (!n->is_table())
    fail(*n, full, quote(full) + " must be a table, not " + type_name(*n),
         n->is_array() ? "write [" + printable(full) + "], not [[" + printable(full) + "]]" : "");
  return n->as_table();
}

std::vector<const toml::table*> Reader::tables(const toml::table& t, std::string_view path,
                                               std::string_view key) const {
  std::vector<const toml::table*> out;
  const toml::node* n = t.get(key);
  if (!n) return out;
  const std::string full = join_key(path, key);
  if (!n->is_array())
    fail(*n, full, quote(full) + " must be an array of tables, not " + type_name(*n),
         "write [[" + printable(full) + "]] above each entry");
  const toml::array& arr = *n->as_array();
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string item = full + "[" + std::to_string(i) + "]";
    if (!arr[i].is_table()) fail(arr[i], item, quote(item) + " must be a table, not " + type_name(arr[i]));
    out.push_back(arr[i].as_table());
  }
  return out;
}

float Reader::number(const toml::node& n, std::string_view key, std::string_view name, Range r) const {
  double v = 0.0;
  if (const auto* i = n.as_integer()) v = static_cast<double>(i->get());
  else if (const auto* f = n.as_floating_point()) v = f->get();
  else fail(n, key, quote(name) + " must be a number, not " + type_name(n));
  // TOML has nan and inf literals; no setting means anything with them.
  if (!std::isfinite(v)) fail(n, key, quote(name) + " must be a finite number, got " + num(v));
  if (std::abs(v) > FLT_MAX) fail(n, key, quote(name) + " = " + num(v) + " is too large for a 32-bit float");
  const float f = static_cast<float>(v);
  if (!r.contains(f)) {
    // A tiny value can pass as a double but round to 0 as a float.
    std::string hint = r.contains(v) ? "it rounds to " + num(f) + " as a 32-bit float" : "";
    fail(n, key, quote(name) + " must be " + r.describe() + ", got " + num(v), std::move(hint));
  }
  return f;
}

bool Reader::read(const toml::table& t, std::string_view path, std::string_view key, Range r,
                  float& out) const {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  out = number(*n, full, full, r);
  return true;
}

bool Reader::read(const toml::table& t, std::string_view path, std::string_view key, Range r,
                  int& out) const {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  const auto* i = n->as_integer();
  if (!i) {
    const auto* f = n->as_floating_point();
    std::string hint = f && std::isfinite(f->get()) && std::trunc(f->get()) == f->get()
                           ? "write it as " + num(f->get())
                           : "";
    fail(*n, full, quote(full) + " must be an integer, not " + type_name(*n), std::move(hint));
  }
  const auto v = static_cast<double>(i->get());
  const Range in_int = {std::max(r.lo, double(INT_MIN)), std::min(r.hi, double(INT_MAX)), r.lo_open, r.hi_open};
  if (!in_int.contains(v)) fail(*n, full, quote(full) + " must be " + in_int.describe() + ", got " + num(v));
  out = static_cast<int>(i->get());
  return true;
}

bool Reader::read(const toml::table& t, std::string_view path, std::string_view key, Range,
                  bool& out) const {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  if (!n->is_boolean()) fail(*n, full, quote(full) + " must be true or false, not " + type_name(*n));
  out = n->as_boolean()->get();
  return true;
}

bool Reader::read(const toml::table& t, std::string_view path, std::string_view key, Range r,
                  glm::vec3& out) const {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  const toml::array* arr = n->as_array();
  if (!arr) fail(*n, full, quote(full) + " must be an array of 3 numbers, not " + type_name(*n));
  if (arr->size() != 3)
    fail(*n, full, quote(full) + " must be an array of 3 numbers, got " + std::to_string(arr->size()) +
                       (arr->size() == 1 ? " element" : " elements"));
  for (int c = 0; c < 3; ++c)
    out[c] = number((*arr)[static_cast<std::size_t>(c)], full, full + "[" + std::to_string(c) + "]", r);
  return true;
}

bool Reader::read(const toml::table& t, std::string_view path, std::string_view key, std::string& out) const {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  if (!n->is_string()) fail(*n, full, quote(full) + " must be a string, not " + type_name(*n));
  out = n->as_string()->get();
  return true;
}

bool Reader::read_choice(const toml::table& t, std::string_view path, std::string_view key, Keys names,
                         std::size_t& index) const {
  std::string s;
  if (!read(t, path, key, s)) return false;
  const auto it = std::find(names.begin(), names.end(), s);
  if (it != names.end()) {
    index = static_cast<std::size_t>(it - names.begin());
    return true;
  }
  const std::string full = join_key(path, key);
  std::string hint = did_you_mean(s, names);
  if (hint.empty()) {
    hint = "expected ";
    for (std::size_t i = 0; i < names.size(); ++i)
      hint.append(i == 0 ? "" : i + 1 == names.size() ? " or " : ", ").append(quote(names[i]));
  }
  fail(*t.get(key), full, "unknown value " + quote(s) + " for " + quote(full), std::move(hint));
}

}  // namespace ms
