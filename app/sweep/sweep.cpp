#include "sweep/sweep.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>

#include "core/clock.h"
#include "io/compare.h"
#include "sweep/sweep_exact.h"
#include "core/error.h"
#include "render/aov.h"
#include "render/frame.h"
#include "render/graph_field.h"
#include "render/gpu_timer.h"
#include "render/scene_drawer.h"
#include "render/uniforms.h"

namespace ms {
namespace {

using Clock = std::chrono::steady_clock;


// One rendered image with its AOVs (empty when not asked for).
struct Frame {
  Image color, aovs;
};

int channel_of(const Image& img, const std::string& name) {
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  if (it == img.channels.end()) fail_system("sweep: the AOV frame has no '" + name + "' channel");
  return static_cast<int>(it - img.channels.begin());
}

// Everything one configuration needs, bound to one context.
class RowRenderer {
 public:
  RowRenderer(const Context& ctx, const Scene& scene, const AssembleOptions& opts, const SweepSettings& s)
      : renderer_(ctx, s.dispatch, s.group), scene_(scene), opts_(opts), s_(s), vs_(fullscreen_vertex_source()),
        post_(vs_, assemble_post(scene.render.tonemap, true, opts)) {}

  Scene scene_for(const SweepConfig& c) const {
    Scene sc = scene_;
    sc.quality = c.quality;
    return sc;
  }
  // The timed frames are drawn as render draws them: in one pass at spp 1.
  bool fused() const { return s_.spp == 1; }
  AssembleOptions opts_for(const SweepConfig& c, bool aovs, bool fused = false) {
    AssembleOptions o = opts_;
    o.cell_size = c.cell_size;
    o.graph = shape_for(c);
    o.defines.insert(o.defines.end(), c.tunables.begin(), c.tunables.end());
    if (aovs)
      for (const auto& d : aov_defines()) o.defines.push_back(d);
    if (fused)
      for (auto& d : fused_post_defines(scene_.render.tonemap, true)) o.defines.push_back(std::move(d));
    return o;
  }
  UniformFn uniforms(const Scene& sc, int w, int h) const {
    return [&sc, w, h, t = s_.time](const Program& p) { set_scene_uniforms(p, sc, w, h, t, 0); };
  }
  FrameParams params(int spp, bool aovs, bool fused = false) const {
    FrameParams fp;
    fp.width = s_.width;
    fp.height = s_.height;
    fp.spp = spp;
    fp.exposure = scene_.render.exposure;
    fp.aovs = aovs;
    fp.fused_post = fused;
    return fp;
  }

  // A graph scene's shape for the row's cell size: the one the command
  // prepared, or one prepared the first time a row of another size asks.
  std::shared_ptr<const GraphParts> shape_for(const SweepConfig& c) {
    if (!scene_.graph) return nullptr;
    if (c.cell_size == opts_.cell_size && opts_.graph) return opts_.graph;
    Field& f = fields_[c.cell_size];
    if (!f.shape) {
      AssembleOptions o = opts_;
      o.cell_size = c.cell_size;
      prepare_graph_shape(scene_, o);
      f.shape = o.graph;
    }
    return f.shape;
  }

  // A graph scene's node buffers and pruned grid for the row's cell size,
  // built the first time a row asks, bound before each of its draws.
  void bind_field(const SweepConfig& c) {
    if (!scene_.graph) return;
    const std::shared_ptr<const GraphParts> shape = shape_for(c);
    Field& f = fields_[c.cell_size];
    if (!f.field && shape->plan.interpret) f.field = std::make_unique<GraphField>(*shape);
    if (f.field) f.field->bind();
  }

  // The image at `spp`, with AOVs when asked.
  Frame render(const SweepConfig& c, int spp, bool aovs) {
    const Scene sc = scene_for(c);
    const std::unique_ptr<Program> prog = renderer_.program(assemble_scene(sc, opts_for(c, aovs)));
    bind_field(c);
    renderer_.draw_program(*prog, uniforms(sc, s_.width, s_.height), post_, params(spp, aovs));
    Frame f;
    f.color = renderer_.read_color();
    if (aovs) f.aovs = renderer_.read_aovs();
    return f;
  }

  // Compile one row's plain program (timed, with a 1x1 frame that forces
  // llvmpipe's lazy code generation), then render its image and AOVs with
  // the AOV build, whose colour is bit-identical to the plain one's
  // (tests/cli/test_fused_post.cpp).
  std::unique_ptr<Program> compile(const SweepConfig& c, SweepRow& row, Frame& image) {
    const Scene sc = scene_for(c);
    const ShaderSource src = assemble_scene(sc, opts_for(c, false, fused()));
    const Clock::time_point t0 = Clock::now();
    std::unique_ptr<Program> prog = renderer_.program(src);
    bind_field(c);
    FrameParams tiny = params(1, false, fused());
    tiny.width = tiny.height = 1;
    renderer_.draw_program(*prog, uniforms(sc, 1, 1), post_, tiny);
    glFinish();
    row.compile_ms = ms_since(t0);
    image = render(c, s_.spp, true);
    row.cost = measure_cost(image.aovs);
    return prog;
  }

  // One round of one row: warm-up frames, then timed ones; appends the
  // times and returns this round's medians.
  struct Medians {
    double gpu, wall, cpu;
  };
  Medians time_round(const Program& prog, const SweepConfig& c, std::vector<double>& gpu, std::vector<double>& wall,
                     std::vector<double>& cpu) {
    const Scene sc = scene_for(c);
    const FrameParams fp = params(s_.spp, false, fused());
    bind_field(c);
    for (int i = 0; i < s_.warmup; ++i) renderer_.draw_program(prog, uniforms(sc, s_.width, s_.height), post_, fp);
    glFinish();
    std::vector<double> g, w, u;
    for (int i = 0; i < s_.frames; ++i) {
      const Clock::time_point w0 = Clock::now();
      const double u0 = process_cpu_ms();
      timer_.begin();
      renderer_.draw_program(prog, uniforms(sc, s_.width, s_.height), post_, fp);
      timer_.end();
      glFinish();
      u.push_back(process_cpu_ms() - u0);
      w.push_back(ms_since(w0));
      g.push_back(timer_.wait_ms());
    }
    gpu.insert(gpu.end(), g.begin(), g.end());
    wall.insert(wall.end(), w.begin(), w.end());
    cpu.insert(cpu.end(), u.begin(), u.end());
    return {summarize(g).median, summarize(w).median, summarize(u).median};
  }

 private:
  SceneDrawer renderer_;  // the fragment pass or the compute dispatch (s.dispatch)
  const Scene& scene_;
  const AssembleOptions& opts_;
  const SweepSettings& s_;
  std::string vs_;
  Program post_;
  GpuTimer timer_;
  struct Field {
    std::shared_ptr<const GraphParts> shape;  // null for the command's own cell size
    std::unique_ptr<GraphField> field;        // null for a graph written inline
  };
  std::map<float, Field> fields_;
};

// Depth and hit/miss of `aovs` against a reference given per pixel. A pixel
// counts as a hit when most of its samples hit; depth is compared where
// every sample of both hit (the AOV depth of a partly covered pixel is
// weighted by coverage).
template <class RefHit, class RefDepth>
void depth_errors(const Image& aovs, RefHit ref_hit, RefDepth ref_depth, SweepError& e) {
  const int hc = channel_of(aovs, "hit"), zc = channel_of(aovs, "Z");
  const size_t n = static_cast<size_t>(aovs.width) * aovs.height, nc = aovs.channels.size();
  double sum = 0, mx = 0;
  size_t both = 0, wrong = 0;
  for (size_t p = 0; p < n; ++p) {
    const float h = aovs.pixels[p * nc + hc];
    const double rh = ref_hit(p);
    if ((h > 0.5f) != (rh > 0.5)) ++wrong;
    if (h < 0.999f || rh < 0.999) continue;
    const double d = std::abs(static_cast<double>(aovs.pixels[p * nc + zc]) - ref_depth(p));
    sum += d;
    mx = std::max(mx, d);
    ++both;
  }
  e.depth_mean = both ? sum / static_cast<double>(both) : 0.0;
  e.depth_max = mx;
  e.misclassified = n ? static_cast<double>(wrong) / static_cast<double>(n) : 0.0;
}

SweepError error_against(const Frame& ref, const Frame& f) {
  SweepError e;
  const CompareMetrics m = compare_images(ref.color, f.color);
  e.psnr = m.psnr;
  e.mae = m.mean_abs;
  if (ref.aovs.pixels.empty() || f.aovs.pixels.empty()) {
    e.depth_mean = e.depth_max = e.misclassified = std::numeric_limits<double>::quiet_NaN();
    return e;
  }
  const Image& r = ref.aovs;
  const int hc = channel_of(r, "hit"), zc = channel_of(r, "Z");
  const size_t nc = r.channels.size();
  depth_errors(
      f.aovs, [&](size_t p) { return static_cast<double>(r.pixels[p * nc + hc]); },
      [&](size_t p) { return static_cast<double>(r.pixels[p * nc + zc]); }, e);
  return e;
}

// `image` against the exact-intersection image of the same row (`exact`)
// and its primary rays against the CPU's exact depths (`x`).
SweepError error_against_exact(const ExactDepth& x, const Frame& exact, const Frame& f) {
  SweepError e;
  const CompareMetrics m = compare_images(exact.color, f.color);
  e.psnr = m.psnr;
  e.mae = m.mean_abs;
  depth_errors(
      f.aovs, [&](size_t p) { return x.hit[p] ? 1.0 : 0.0; }, [&](size_t p) { return x.t[p]; }, e);
  return e;
}

}  // namespace

SweepClock parse_sweep_clock(const std::string& name) {
  if (name == "gpu") return SweepClock::gpu;
  if (name == "wall") return SweepClock::wall;
  if (name == "cpu") return SweepClock::cpu;
  fail_input("unknown clock '" + name + "'", {}, 0, "--time-by", "use gpu, wall or cpu");
}

const char* sweep_clock_name(SweepClock c) {
  return c == SweepClock::cpu ? "cpu" : c == SweepClock::wall ? "wall" : "gpu";
}

double row_time_ms(const SweepResult& r, const SweepRow& row) {
  switch (r.clock) {
    case SweepClock::cpu: return row.cpu_best_median;
    case SweepClock::wall: return row.wall_best_median;
    case SweepClock::gpu: break;
  }
  return r.gpu_timer ? row.gpu_best_median : row.wall_best_median;
}

void mark_pareto(SweepResult& r) {
  auto mark = [&](auto psnr, auto set) {
    for (SweepRow& a : r.rows) {
      bool dominated = false;
      for (const SweepRow& b : r.rows) {
        if (&a == &b) continue;
        const double ta = row_time_ms(r, a), tb = row_time_ms(r, b), pa = psnr(a), pb = psnr(b);
        if (tb <= ta && pb >= pa && (tb < ta || pb > pa)) {
          dominated = true;
          break;
        }
      }
      set(a, !dominated);
    }
  };
  mark([](const SweepRow& x) { return x.same_spp.psnr; }, [](SweepRow& x, bool v) { x.pareto_same_spp = v; });
  mark([](const SweepRow& x) { return x.supersampled.psnr; }, [](SweepRow& x, bool v) { x.pareto_supersampled = v; });
}

SweepResult run_sweep(const Context& ctx, const Scene& scene, const std::vector<SweepConfig>& configs,
                      const AssembleOptions& opts, const SweepSettings& s,
                      const std::function<void(size_t, const std::string&)>& progress) {
  check_frame_size(ctx.info(), s.width, s.height, 6);  // the AOV frame's targets
  SweepResult result;
  result.backend = ctx.backend();
  result.gl_renderer = ctx.info().renderer;
  result.gl_vendor = ctx.info().vendor;
  result.gl_version = ctx.info().version;
  result.dispatch = s.dispatch == Dispatch::compute ? Dispatch::compute : Dispatch::fragment;
  RowRenderer rr(ctx, scene, opts, s);

  // The references: converged tracing, the scene's own shading.
  const SweepConfig ref{"reference", "preset", sweep_preset_quality(scene.quality, "reference"), {}};
  result.reference_quality = ref.quality;
  if (progress) progress(0, "references (same spp, " + std::to_string(s.ref_spp) + " spp, exact)");
  const Frame ref_same = rr.render(ref, s.spp, true);
  const Frame ref_super = rr.render(ref, s.ref_spp, false);
  std::string why;
  const std::optional<std::vector<ExactSphere>> spheres =
      s.spp == 1 ? exact_spheres(scene, &why) : std::nullopt;
  if (s.spp != 1) why = "needs --spp 1 (one ray per pixel centre)";
  std::optional<ExactDepth> exact;
  if (spheres) exact = exact_depth(scene.camera, s.width, s.height, *spheres, scene.planes, ref.quality.max_distance);
  result.exact_status = exact ? "available" : why;
  // A row's exact image: its own settings, its rays intersected exactly.
  const auto exact_image = [&](const SweepConfig& c) {
    SweepConfig x = c;
    for (auto& d : exact_sphere_defines(*spheres)) x.tunables.push_back(std::move(d));
    return rr.render(x, s.spp, false);
  };

  // Compile and render every row (errors need only one image), keeping the
  // programs for the timing rounds.
  std::vector<std::unique_ptr<Program>> programs;
  for (size_t i = 0; i < configs.size(); ++i) {
    if (progress) progress(i + 1, configs[i].name);
    SweepRow row;
    row.config = configs[i];
    Frame f;
    programs.push_back(rr.compile(configs[i], row, f));
    row.same_spp = error_against(ref_same, f);
    row.supersampled = error_against(ref_super, f);
    if (exact) row.exact = error_against_exact(*exact, exact_image(configs[i]), f);
    result.rows.push_back(std::move(row));
  }
  // Timing rounds, every row in turn in each.
  std::vector<std::vector<double>> gpu(configs.size()), wall(configs.size()), cpu(configs.size());
  for (int round = 0; round < s.rounds; ++round) {
    if (progress) progress(0, "timing round " + std::to_string(round + 1) + " of " + std::to_string(s.rounds));
    for (size_t i = 0; i < configs.size(); ++i) {
      const auto m = rr.time_round(*programs[i], configs[i], gpu[i], wall[i], cpu[i]);
      SweepRow& row = result.rows[i];
      row.gpu_best_median = round == 0 ? m.gpu : std::min(row.gpu_best_median, m.gpu);
      row.wall_best_median = round == 0 ? m.wall : std::min(row.wall_best_median, m.wall);
      row.cpu_best_median = round == 0 ? m.cpu : std::min(row.cpu_best_median, m.cpu);
    }
  }
  bool any_gpu = false;
  for (size_t i = 0; i < configs.size(); ++i) {
    result.rows[i].gpu_ms = summarize(gpu[i]);
    result.rows[i].wall_ms = summarize(wall[i]);
    result.rows[i].cpu_ms = summarize(cpu[i]);
    any_gpu = any_gpu || result.rows[i].gpu_ms.max > 0.0;
  }
  result.gpu_timer = any_gpu;
  result.clock = s.clock;
  mark_pareto(result);
  return result;
}

}  // namespace ms
