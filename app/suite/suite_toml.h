// TOML reads the suite loader needs beyond scene/toml_read.h's Reader:
// doubles (thresholds must read back exactly), strings or lists of them,
// integer pairs, and keys layered over [defaults]. Errors go through
// Reader::fail: file, line, key and a did-you-mean.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "scene/toml_read.h"

namespace ms {

using Views = std::vector<std::string_view>;

// t[key] as a double in `range` (inf only when allow_inf); false when absent.
bool read_double(const Reader& r, const toml::table& t, std::string_view path, std::string_view key, Range range,
                 double& out, bool allow_inf = false);

// A string or an array of strings, each one of `allowed` when it is not empty.
std::vector<std::string> read_strings(const Reader& r, const toml::table& t, std::string_view path,
                                      std::string_view key, const Views& allowed = {});

// [A, B] of integers in `range`; false when absent.
bool read_int_pair(const Reader& r, const toml::table& t, std::string_view path, std::string_view key, Range range,
                   std::pair<int, int>& out);

// Keys of a table, from it or else from its [defaults] counterpart: a
// case's keys, or those of its [case.cost] / [case.frame_time] (one key at
// a time, so a case can set one bound and inherit the rest).
struct CaseTables {
  const toml::table* own;
  const toml::table* defaults;
  std::string path;                      // "case[2]", "case[2].cost"
  std::string defaults_path = "defaults";  // "defaults", "defaults.cost"
  std::pair<const toml::table*, std::string> at(std::string_view key) const {
    if (own && own->contains(key)) return {own, path};
    if (defaults && defaults->contains(key)) return {defaults, defaults_path};
    return {nullptr, path};
  }
  int line(std::string_view key) const {
    const auto [t, p] = at(key);
    if (t) return Reader::line_of(*t, key);
    return own ? Reader::line_of(*own) : defaults ? Reader::line_of(*defaults) : 0;
  }
  // The [name] sub-tables of both, layered the same way.
  CaseTables sub(const Reader& r, std::string_view name) const {
    return {own ? r.table(*own, path, name) : nullptr, defaults ? r.table(*defaults, defaults_path, name) : nullptr,
            join_key(path, name), join_key(defaults_path, name)};
  }
  bool any() const { return own || defaults; }
};

}  // namespace ms
