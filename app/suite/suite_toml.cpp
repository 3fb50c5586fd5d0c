#include "suite/suite_toml.h"

#include <algorithm>
#include <cmath>

#include "core/suggest.h"

namespace ms {

// A number as a double (thresholds are compared with doubles, and a value
// that compare --json printed must read back exactly).
bool read_double(const Reader& r, const toml::table& t, std::string_view path, std::string_view key, Range range,
                 double& out, bool allow_inf) {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  double v = 0;
  if (const auto* i = n->as_integer()) v = static_cast<double>(i->get());
  else if (const auto* f = n->as_floating_point()) v = f->get();
  else r.fail(*n, full, quote(full) + " must be a number");
  if (std::isnan(v) || (std::isinf(v) && !allow_inf)) r.fail(*n, full, quote(full) + " must be a finite number");
  if (!std::isinf(v) && !range.contains(v))
    r.fail(*n, full, quote(full) + " must be " + range.describe() + ", got " + format_number(v));
  out = v;
  return true;
}

// A string or an array of strings, each one of `allowed` when given.
std::vector<std::string> read_strings(const Reader& r, const toml::table& t, std::string_view path,
                                      std::string_view key, const Views& allowed) {
  std::vector<std::string> out;
  const toml::node* n = t.get(key);
  if (!n) return out;
  const std::string full = join_key(path, key);
  std::vector<const toml::node*> items;
  if (n->is_string()) items.push_back(n);
  else if (const toml::array* a = n->as_array()) for (const toml::node& e : *a) items.push_back(&e);
  else r.fail(*n, full, quote(full) + " must be a string or an array of strings");
  for (const toml::node* e : items) {
    if (!e->is_string()) r.fail(*e, full, quote(full) + " must hold strings only");
    std::string s = e->as_string()->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
      std::string hint = did_you_mean(s, allowed);
      if (hint.empty())
        for (std::string_view a : allowed) hint.append(hint.empty() ? "use " : ", ").append(a);
      r.fail(*e, full, "unknown value " + quote(s) + " for " + quote(full), hint);
    }
    out.push_back(std::move(s));
  }
  return out;
}

// [A, B] of integers in `range`.
bool read_int_pair(const Reader& r, const toml::table& t, std::string_view path, std::string_view key, Range range,
                   std::pair<int, int>& out) {
  const toml::node* n = t.get(key);
  if (!n) return false;
  const std::string full = join_key(path, key);
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2 || !(*a)[0].is_integer() || !(*a)[1].is_integer())
    r.fail(*n, full, quote(full) + " must be an array of 2 integers", key == "size" ? "e.g. size = [160, 90]" : "");
  const auto x = (*a)[0].as_integer()->get(), y = (*a)[1].as_integer()->get();
  if (!range.contains(static_cast<double>(x)) || !range.contains(static_cast<double>(y)))
    r.fail(*n, full, quote(full) + " values must be " + range.describe());
  out = {static_cast<int>(x), static_cast<int>(y)};
  return true;
}

}  // namespace ms
