#include "cli/dispatch_probe.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/cache_dir.h"
#include "render/scene_drawer.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

struct CacheLine {
  std::string renderer, version, choice;
};

// The file's lines; `corrupt` when any does not parse (then none is trusted).
std::vector<CacheLine> read_cache(const fs::path& path, bool& corrupt) {
  corrupt = false;
  std::vector<CacheLine> lines;
  std::ifstream f(path);
  if (!f) return lines;
  std::string line;
  while (std::getline(f, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string field; std::getline(ss, field, '\t');) fields.push_back(field);
    if (fields.size() != 3 || fields[0].empty() || (fields[2] != "fragment" && fields[2] != "compute")) {
      corrupt = true;
      return {};
    }
    lines.push_back({fields[0], fields[1], fields[2]});
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
    const auto t0 = std::chrono::steady_clock::now();
    drawer.draw(graph, post, f.in, f.params);
    glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

fs::path dispatch_cache_path() { return cache_dir() / "dispatch"; }

Dispatch choose_dispatch(Dispatch requested, PassGraph& graph, const Program& post, const StillFrame& frame,
                         const Context& ctx, ComputeGroup group, bool verbose) {
  if (requested != Dispatch::automatic) return requested;
  const auto say = [&](const std::string& text) {
    if (verbose) std::fprintf(stderr, "marchstudio: dispatch auto: %s\n", text.c_str());
  };
  try {
    (void)compute_source(graph.pass(graph.size() - 1), group);
  } catch (const Error& e) {
    say("fragment (this input cannot run as compute: " + e.info().what + ")");
    return Dispatch::fragment;
  }
  const std::string renderer = clean(ctx.info().renderer), version = clean(ctx.info().version);
  const fs::path path = dispatch_cache_path();
  bool corrupt = false;
  std::vector<CacheLine> lines = read_cache(path, corrupt);
  for (const CacheLine& l : lines)
    if (l.renderer == renderer && l.version == version) {
      say(l.choice + " (cached for " + renderer + ", " + version + " in " + path.string() + ")");
      return l.choice == "compute" ? Dispatch::compute : Dispatch::fragment;
    }
  if (corrupt) say("the cache " + path.string() + " is unreadable: ignored, and rewritten after the probe");

  StillFrame f = frame;
  f.params.width = kProbeWidth;
  f.params.height = kProbeHeight;
  f.params.spp = 1;
  f.params.aovs = false;
  f.params.fused_post = false;
  f.params.deadline = nullptr;
  double frag_ms = 0, comp_ms = 0;
  {
    SceneDrawer fragment(ctx, graph, Dispatch::fragment, group);
    frag_ms = median_frame_ms(fragment, graph, post, f);
  }
  {
    SceneDrawer compute(ctx, graph, Dispatch::compute, group);
    comp_ms = median_frame_ms(compute, graph, post, f);
  }
  if (graph.stateful()) graph.reset();  // the probe's frames are not the job's
  const Dispatch choice = comp_ms < frag_ms ? Dispatch::compute : Dispatch::fragment;
  lines.push_back({renderer, version, dispatch_name(choice)});
  std::string text;
  for (const CacheLine& l : lines) text += l.renderer + "\t" + l.version + "\t" + l.choice + "\n";
  std::string where = "cached in " + path.string();
  try {
    write_file_atomic(path, text);
  } catch (const Error& e) {  // a cache that cannot be written costs a probe next time, nothing more
    where = "not cached: " + e.info().what;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "probe: fragment %.2f ms, compute %.2f ms a frame at %dx%d: ", frag_ms, comp_ms,
                kProbeWidth, kProbeHeight);
  say(buf + std::string(dispatch_name(choice)) + ", " + where);
  return choice;
}

}  // namespace ms
