#include "scene/graph_read.h"

#include <cmath>

#include "core/error.h"
#include "core/format.h"

namespace ms {

void GraphReader::fail(int v, const std::string& what, const std::string& hint) const {
  fail_input(what, display_, doc_.at(v).line, prefix_ + doc_.pointer(v), hint);
}

float GraphReader::number(int v, const std::string& what) const {
  if (doc_.at(v).kind != JsonKind::number) fail(v, what + " must be a number");
  const double d = doc_.at(v).number;
  if (!std::isfinite(d) || std::fabs(d) > 1e30) fail(v, what + " must be a finite number");
  return static_cast<float>(d);
}

std::vector<float> GraphReader::numbers(int v, int size, const std::string& what) const {
  if (size == 1) return {number(v, what)};
  const JsonValue& a = doc_.at(v);
  if (a.kind != JsonKind::array || a.count != size)
    fail(v, what + " must be an array of " + std::to_string(size) + " numbers",
         a.kind == JsonKind::array ? "it has " + std::to_string(a.count) : "");
  std::vector<float> out;
  for (int c = a.first; c != -1; c = doc_.at(c).next) out.push_back(number(c, "each element of " + what));
  return out;
}

std::vector<float> GraphReader::read_params(int v, const std::vector<GraphParam>& defs) const {
  std::vector<float> out;
  bool ranges = false, bounded = false;
  for (const GraphParam& p : defs) {
    if (p.derived) {
      out.insert(out.end(), static_cast<std::size_t>(p.size), 0.0f);
      continue;
    }
    const int c = doc_.member(v, p.name);
    if (c == -1 && p.optional) {
      out.insert(out.end(), p.fallback, p.fallback + p.size);
      continue;
    }
    if (p.range) {
      const std::vector<float> r = range(c, p.name);
      ranges = true;
      bounded = bounded || r[0] > -kOpenBound || r[1] < kOpenBound;
      out.insert(out.end(), r.begin(), r.end());
      continue;
    }
    if (c == -1) fail(v, "missing parameter " + quote(p.name), describe(defs));
    const std::vector<float> xs = numbers(c, p.size, quote(p.name));
    for (float x : xs)
      if (p.nonneg && x < 0.0f) fail(c, quote(p.name) + " must not be negative", "it is a size");
    for (float x : xs)
      if (p.fraction && !(x >= 0.0f && x <= 1.0f)) fail(c, quote(p.name) + " must be in [0, 1]", "it is a weight");
    if (p.unit) unit(c, p.name, xs);
    out.insert(out.end(), xs.begin(), xs.end());
  }
  if (ranges && !bounded) fail(v, "it bounds no axis: it would be all of space", describe(defs));
  return out;
}

// A range parameter (graph_vocab.h): absent, [min, max], either end null
// (TOML: -inf, inf) for open.
std::vector<float> GraphReader::range(int c, std::string_view name) const {
  if (c == -1) return {-kOpenBound, kOpenBound};
  const JsonValue& a = doc_.at(c);
  if (a.kind != JsonKind::array || a.count != 2)
    fail(c, quote(name) + " must be [min, max]", "null leaves an end open");
  std::vector<float> out;
  for (int e = a.first; e != -1; e = doc_.at(e).next) {
    const float open = out.empty() ? -kOpenBound : kOpenBound;
    const double d = doc_.at(e).number;
    if (doc_.at(e).kind == JsonKind::null || (doc_.at(e).kind == JsonKind::number && d == double(open) * INFINITY)) {
      out.push_back(open);
      continue;
    }
    const float x = number(e, "each end of " + quote(name));
    if (std::fabs(x) > kMaxCoord)
      fail(e, "each end of " + quote(name) + " must be within 1e+18, as float coordinates hold",
           "null leaves an end open");
    out.push_back(x);
  }
  if (out[0] > out[1]) fail(c, quote(name) + " must have min <= max", "it is [min, max]");
  return out;
}

void GraphReader::unit(int c, std::string_view name, const std::vector<float>& xs) const {
  const double len = std::sqrt(double(xs[0]) * xs[0] + double(xs[1]) * xs[1] + double(xs[2]) * xs[2]);
  if (std::fabs(len - 1.0) > 1e-4)
    fail(c, quote(name) + " must have length 1 (it has " + format_number(len) + ")",
         len > 0.0 ? "divide it by its length, and w with it to keep the plane"
                   : "it is the plane's normal");
}

std::string GraphReader::describe(const std::vector<GraphParam>& defs) {
  std::string s;
  for (const GraphParam& d : defs) {
    if (d.derived) continue;
    s += (s.empty() ? "" : ", ") + std::string(d.name) + (d.size > 1 ? " (" + std::to_string(d.size) + " numbers)" : "") +
         (d.optional ? " (optional)" : "");
  }
  return s.empty() ? "it takes none" : "it takes " + s;
}

}  // namespace ms
