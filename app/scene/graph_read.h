// The scene graph builder's reading of one node's values (graph_build.h):
// numbers, vectors, a function's parameters by its vocabulary entry, each
// refused as one line naming the file, the line and the JSON pointer.
//
//   GraphReader r(doc, "part.json", "");
//   std::vector<float> p = r.read_params(v, graph_primitives()[fn].params);
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "io/json_doc.h"
#include "scene/graph_vocab.h"

namespace ms {

// Past this a float length() of a box corner overflows (sqrt(FLT_MAX) is
// 1.8e19), and the tracer's distances with it: world coordinates, lengths
// and accumulated scales (and their inverses) of a graph stay within it.
inline constexpr double kMaxCoord = 1e18;

class GraphReader {
 public:
  GraphReader(const JsonDoc& doc, std::string display, std::string prefix)
      : doc_(doc), display_(std::move(display)), prefix_(std::move(prefix)) {}

  [[noreturn]] void fail(int v, const std::string& what, const std::string& hint = {}) const;
  float number(int v, const std::string& what) const;
  // A number (size 1) or an array of `size` numbers.
  std::vector<float> numbers(int v, int size, const std::string& what) const;
  // Node `v`'s parameters in the order of `defs`, flattened.
  std::vector<float> read_params(int v, const std::vector<GraphParam>& defs) const;
  static std::string describe(const std::vector<GraphParam>& defs);

 protected:
  const JsonDoc& doc_;
  std::string display_, prefix_;

 private:
  std::vector<float> range(int c, std::string_view name) const;
  void unit(int c, std::string_view name, const std::vector<float>& xs) const;
  std::vector<float> vertices(int c, const GraphParam& p) const;
};

}  // namespace ms
