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
    if (p.points > 0) {
      const std::vector<float> vs = vertices(c, p);
      out.insert(out.end(), vs.begin(), vs.end());
      continue;
    }
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

// A vertex list (GraphParam::points): [[x, y], ...], 3 to p.points of them,
// no two in a row the same (an edge of no length has no direction).
std::vector<float> GraphReader::vertices(int c, const GraphParam& p) const {
  const JsonValue& a = doc_.at(c);
  const std::string what = quote(p.name);
  if (a.kind != JsonKind::array || a.count < 3 || a.count > p.points)
    fail(c, what + " must be an array of 3 to " + std::to_string(p.points) + " [x, y] points",
         a.kind == JsonKind::array ? "it has " + std::to_string(a.count) : "the polygon's vertices, in order");
  std::vector<float> out{static_cast<float>(a.count)};
  for (int e = a.first; e != -1; e = doc_.at(e).next) {
    const std::vector<float> xy = numbers(e, 2, "each point of " + what);
    for (float x : xy)
      if (std::fabs(x) > kMaxCoord) fail(e, "each point of " + what + " must be within 1e+18, as float coordinates hold");
    const std::size_t n = out.size();
    const bool repeats = n > 1 && out[n - 2] == xy[0] && out[n - 1] == xy[1];
    const bool closes = doc_.at(e).next == -1 && out[1] == xy[0] && out[2] == xy[1];
    if (repeats || closes)
      fail(e, "a point of " + what + " repeats the one before it", "the polygon closes itself: give each vertex once");
    out.insert(out.end(), xy.begin(), xy.end());
  }
  while (out.size() < static_cast<std::size_t>(p.size)) out.insert(out.end(), {out[out.size() - 2], out[out.size() - 1]});
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
    const std::string shape = d.points > 0 ? " (3 to " + std::to_string(d.points) + " [x, y] points)"
                              : d.size > 1  ? " (" + std::to_string(d.size) + " numbers)"
                                            : "";
    s += (s.empty() ? "" : ", ") + std::string(d.name) + shape +
         (d.optional ? " (optional)" : "");
  }
  return s.empty() ? "it takes none" : "it takes " + s;
}

}  // namespace ms
