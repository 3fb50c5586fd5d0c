#include "pipeline/dispatch_probe.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "core/clock.h"
#include "core/error.h"
#include "io/cache_dir.h"
#include "pipeline/dispatch_plan.h"
#include "pipeline/input.h"
#include "render/scene_drawer.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

struct CacheLine {
  std::string renderer, version, text;
  DispatchChoice choice;
};

std::string choice_text(const DispatchChoice& c) {
  return c.dispatch == Dispatch::compute ? "compute " + group_name(c.group) : "fragment";
}

// "fragment", "compute" (8x8: the format before groups were measured) or
// "compute WxH[/S]"; none for anything else.
std::optional<DispatchChoice> parse_choice(const std::string& text) {
  if (text == "fragment") return DispatchChoice{Dispatch::fragment, {}};
  if (text == "compute") return DispatchChoice{Dispatch::compute, {}};
  if (text.rfind("compute ", 0) != 0) return std::nullopt;
  if (const std::optional<ComputeGroup> g = parse_group_name(text.substr(8))) return DispatchChoice{Dispatch::compute, *g};
  return std::nullopt;
}

// The file's lines; `corrupt` when any does not parse (then none is trusted).
std::vector<CacheLine> read_cache(const fs::path& path, bool& corrupt) {
  corrupt = false;
  std::vector<CacheLine> lines;
  std::string text;
  if (!read_cache_file(path, text)) return lines;  // missing, or not a regular file: a miss
  std::istringstream f(text);
  std::string line;
  while (std::getline(f, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, '\t');) fields.push_back(field);
    std::optional<DispatchChoice> choice;
    if (fields.size() == 3 && !fields[0].empty()) choice = parse_choice(fields[2]);
    if (!choice) {
      corrupt = true;
      return {};
    }
    lines.push_back({fields[0], fields[1], fields[2], *choice});
  }
  return lines;
}

// Tabs and newlines would break the line format; a driver string has none,
// but a cache file must never be made unreadable by one.
std::string clean(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
  return s;
}

double median_frame_ms(SceneDrawer& drawer, PassGraph& graph, const Program& post, const StillFrame& f) {
  drawer.draw(graph, post, f.in, f.params);  // warm-up: llvmpipe compiles lazily at the first draw
  glFinish();
  std::vector<double> ms;
  for (int i = 0; i < kProbeFrames; ++i) {
    const Stopwatch t;
    drawer.draw(graph, post, f.in, f.params);
    glFinish();
    ms.push_back(t.ms());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

fs::path dispatch_cache_path() {
  const fs::path dir = cache_dir();
  return dir.empty() ? fs::path() : dir / "dispatch";
}

void check_compute_input(Dispatch d, const LoadedInput& in) {
  if (d == Dispatch::compute) (void)compute_source(in.passes.back());
}

DispatchChoice choose_dispatch(Dispatch requested, PassGraph& graph, const Program& post, const StillFrame& frame,
                               const Context& ctx, std::optional<ComputeGroup> group, bool verbose) {
  if (requested != Dispatch::automatic) return {requested, group.value_or(ComputeGroup{})};
  const auto say = [&](const std::string& text) {
    if (verbose) std::fprintf(stderr, "marchstudio: dispatch auto: %s\n", text.c_str());
  };
  try {
    (void)compute_source(graph.pass(graph.size() - 1), group.value_or(ComputeGroup{}));
  } catch (const Error& e) {
    say("fragment (this input cannot run as compute: " + e.info().what + ")");
    return {Dispatch::fragment, group.value_or(ComputeGroup{})};
  }
  const std::string renderer = clean(ctx.info().renderer), version = clean(ctx.info().version);
  const fs::path path = dispatch_cache_path();
  bool corrupt = false;
  std::vector<CacheLine> lines = read_cache(path, corrupt);
  for (const CacheLine& l : lines)
    if (l.renderer == renderer && l.version == version) {
      DispatchChoice c = l.choice;
      if (group) c.group = *group;  // a given group is what compute draws with
      say(choice_text(c) + " (cached for " + renderer + ", " + version + " in " + path.string() + ")");
      return c;
    }
  if (corrupt) say("the cache " + path.string() + " is unreadable: ignored, and rewritten after the probe");

  StillFrame f = frame;
  f.params.spp = 1;
  f.params.aovs = false;
  f.params.fused_post = false;
  f.params.deadline = nullptr;
  // One drawer per dispatch and group, each compiled once for all sizes.
  std::unique_ptr<SceneDrawer> fragment;
  std::map<std::string, std::unique_ptr<SceneDrawer>> compute;
  const DispatchProbe p = plan_dispatch(group, [&](Dispatch d, ComputeGroup g, int w, int h) {
    std::unique_ptr<SceneDrawer>& drawer = d == Dispatch::fragment ? fragment : compute[group_name(g)];
    if (!drawer) drawer = std::make_unique<SceneDrawer>(ctx, graph, d, g);
    f.params.width = w;
    f.params.height = h;
    return median_frame_ms(*drawer, graph, post, f);
  });
  fragment.reset();
  compute.clear();
  if (graph.stateful()) graph.reset();  // the probe's frames are not the job's
  lines.push_back({renderer, version, choice_text(p.choice), p.choice});
  std::string text;
  for (const CacheLine& l : lines) text += l.renderer + "\t" + l.version + "\t" + l.text + "\n";
  // A cache that cannot be written costs a probe next time, nothing more.
  std::string where = "cached in " + path.string(), why;
  if (!write_cache_file(path, text, &why)) where = "not cached: " + why;
  say("probe: " + describe_probe(p) + ": " + choice_text(p.choice) + ", " + where);
  return p.choice;
}

}  // namespace ms
