#include "cli/dispatch_flag.h"

#include <cstdio>

#include "core/error.h"

namespace ms {

Dispatch parse_dispatch(const std::string& name) {
  if (name == "fragment") return Dispatch::fragment;
  if (name == "compute") return Dispatch::compute;
  if (name == "auto") return Dispatch::automatic;
  fail_input("--dispatch '" + name + "' is not one of fragment, compute, auto", {}, 0, "--dispatch");
}

GraphEval parse_graph_eval(const std::string& name) {
  if (name == "inline") return GraphEval::inline_;
  if (name == "interpreter") return GraphEval::interpreter;
  if (name == "auto") return GraphEval::auto_;
  fail_input("--graph-eval '" + name + "' is not one of inline, interpreter, auto", {}, 0, "--graph-eval");
}

std::optional<ComputeGroup> parse_compute_group(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::optional<ComputeGroup> g = parse_group_name(text);
  if (!g)
    fail_input("--compute-group '" + text + "' must be WxH with 1..1024 invocations, e.g. 8x8, or WxH/N for stripes of N group rows",
               {}, 0, "--compute-group");
  return g;
}


}  // namespace ms
