// Typed, range-checked reads from a parsed TOML table, each failure an
// ms::Error naming file:line and the dotted key. load.cpp describes each
// scene table as a list of Fields and lets these helpers do the checking,
// so adding a key is one line there, not a new if-chain.
#pragma once
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>
#include <toml++/toml.h>

#include "core/format.h"

namespace ms {

// Accepted values of a number; vec3 fields apply it to each component.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;

  static constexpr Range any() { return {}; }
  static constexpr Range at_least(double lo) { return {lo, Range{}.hi, false, false}; }
  static constexpr Range above(double lo) { return {lo, Range{}.hi, true, false}; }
  static constexpr Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static constexpr Range open(double lo, double hi) { return {lo, hi, true, true}; }
  bool contains(double v) const;
  std::string describe() const;  // "> 0", ">= 1", "in [1, 1024]", "in (0, 180)"
};

// One key of a table and the struct member it fills.
template <class T>
struct Field {
  std::string_view key;
  std::variant<float T::*, int T::*, bool T::*, glm::vec3 T::*> member;
  Range range = Range::any();
};

using Keys = std::span<const std::string_view>;

// "camera" + "fov" -> "camera.fov"; "" + "camera" -> "camera".
std::string join_key(std::string_view path, std::string_view key);

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(int line, std::string_view key, std::string what, std::string hint = {}) const;
  [[noreturn]] void fail(const toml::node& at, std::string_view key, std::string what,
                         std::string hint = {}) const;
  // Line of t[key] when present, else of the table itself (0 when unknown).
  static int line_of(const toml::table& t, std::string_view key = {});

  // Every key of `t` must be in `known`. The hint is a did-you-mean over
  // `known`, else whatever `elsewhere(key)` says (e.g. "belongs in [render]").
  void check_keys(const toml::table& t, std::string_view path, Keys known,
                  const std::function<std::string(std::string_view)>& elsewhere = {}) const;

  // t[key] as a table (nullptr when absent), or as an array of tables.
  const toml::table* table(const toml::table& t, std::string_view path, std::string_view key) const;
  std::vector<const toml::table*> tables(const toml::table& t, std::string_view path,
                                         std::string_view key) const;

  // Read t[key] into `out`; leave it unchanged and return false when absent.
  bool read(const toml::table& t, std::string_view path, std::string_view key, Range r, float& out) const;
  bool read(const toml::table& t, std::string_view path, std::string_view key, Range r, int& out) const;
  bool read(const toml::table& t, std::string_view path, std::string_view key, Range r, bool& out) const;
  bool read(const toml::table& t, std::string_view path, std::string_view key, Range r,
            glm::vec3& out) const;
  bool read(const toml::table& t, std::string_view path, std::string_view key, std::string& out) const;
  // A string from `names`; the enum's values must follow the same order.
  template <class E>
  bool read_enum(const toml::table& t, std::string_view path, std::string_view key, Keys names,
                 E& out) const {
    std::size_t i = 0;
    if (!read_choice(t, path, key, names, i)) return false;
    out = static_cast<E>(i);
    return true;
  }

  // Fill `out` from every field present in `t`.
  template <class T, std::size_t N>
  void read_fields(const toml::table& t, std::string_view path, const Field<T> (&fields)[N], T& out) const {
    for (const Field<T>& f : fields)
      std::visit([&](auto member) { read(t, path, f.key, f.range, out.*member); }, f.member);
  }

 private:
  bool read_choice(const toml::table& t, std::string_view path, std::string_view key, Keys names,
                   std::size_t& index) const;
  float number(const toml::node& n, std::string_view key, std::string_view name, Range r) const;

  std::string file_;
};

// The keys a Field list accepts, plus `extra` ones read by hand.
template <class T, std::size_t N>
std::vector<std::string_view> keys_of(const Field<T> (&fields)[N], std::initializer_list<std::string_view> extra = {}) {
  std::vector<std::string_view> out(extra);
  for (const Field<T>& f : fields) out.push_back(f.key);
  return out;
}

}  // namespace ms
