#include "live/session.h"

#include <chrono>

#include "core/clock.h"
#include "core/error.h"
#include "pipeline/input.h"
#include "scene/graph_animation.h"
#include "scene/quality.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

bool same_camera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up && a.fov_deg == b.fov_deg;
}

}  // namespace

std::string shown_error(ErrorInfo e) {
  if (const size_t at = e.hint.find(kVerboseHint); at != std::string::npos && !e.detail.empty())
    e.hint.replace(at, kVerboseHint.size(), "the full log is below");
  return format_error(e);
}

void Session::set_preset(const std::string& name) {
  preset_ = name;
  if (!disk_ok_) return;  // reload(true) applies it to what it reads
  const Quality cur = scene_.quality;
  scene_.quality = preset_.empty() ? file_scene_.quality : with_preset(file_scene_.quality, preset_);
  scene_.quality.shadows = cur.shadows;
  scene_.quality.ao = cur.ao;
  scene_.quality.reflections = cur.reflections;
  scene_.quality.checker_filter = cur.checker_filter;
}

bool Session::reads_keyboard() const {
  for (size_t i = 0; graph_ && i < graph_->size(); ++i)
    for (const GraphInput& in : graph_->pass(i).inputs)
      if (in.kind == InputKind::keyboard) return true;
  return false;
}

Session::PreparedReload Session::prepare(bool from_disk) {
  PreparedReload p;
  ReloadResult& r = p.result;
  p.t0 = Clock::now();
  try {
    if (from_disk || !disk_ok_) {
      Scene fresh;
      try {
        fresh = read_input_scene(opts_.input, opts_.assemble, opts_.set);  // pipeline/input.h
      } catch (const Error&) {
        disk_ok_ = false;
        throw;
      }
      r.camera_changed = !disk_ok_ || !same_camera(fresh.camera, file_scene_.camera);
      disk_ok_ = true;
      file_scene_ = fresh;
      scene_ = fresh;  // a saved TOML replaces the panel's values
      if (!preset_.empty()) scene_.quality = with_preset(fresh.quality, preset_);
    }
    AssembleOptions opts = opts_.assemble;
    prepare_graph(opts, p);  // before anything is assembled: every pass reads the one shape
    const bool specialized = !shadertoy() && opts.specialize != Specialization::generic;
    // Remembered before anything can fail: a failed build must not make
    // every frame retry the same features (features_changed()).
    specialized_ = specialized;
    if (specialized) {
      features_ = derive_features(scene_, features_.library);
      features_ = scene_features(scene_, opts);
    }
    const int view = shadertoy() ? 0 : debug_view;
    if (view > 0) opts.defines.emplace_back("DEBUG_VIEW", std::to_string(view));
    p.fused = fuse_frame(scene_, accumulate_, view, shadertoy());  // render's one pass at spp 1
    if (p.fused)
      for (auto& d : fused_post_defines(scene_.render.tonemap, true)) opts.defines.push_back(std::move(d));
    // The same passes `render` builds (pipeline/input.h), with the viewer's
    // own features when specialized.
    ShaderProject project;
    p.passes = assemble_passes(scene_, has_toml() ? scene_.file : fs::path{}, opts, project, p.warnings,
                               specialized ? &features_ : nullptr);
    deps_.clear();  // preprocessing worked: these are the files now
    for (const PassSource& ps : p.passes)
      deps_.insert(deps_.end(), ps.source.dependencies.begin(), ps.source.dependencies.end());
    // A debug view shows values, not radiance: its post pass stores them as
    // they are (no tone map, no sRGB encode; exposure 1, display_exposure()).
    const bool bloom = scene_.bloom.enabled && !shadertoy() && view == 0;  // docs/post.md
    p.post_src = assemble_post(scene_.render.tonemap, !shadertoy() && view == 0, opts_.assemble, shadertoy(), bloom);
    if (bloom) p.bloom_src = {assemble_bloom(false, opts_.assemble), assemble_bloom(true, opts_.assemble)};
    p.view = view;
    r.cached = cache_.contains(fullscreen_vertex_source(), p.passes.back().source);
    r.ok = true;
  } catch (const Error& e) {
    fail(e, r);
  }
  r.assemble_ms = ms_since(p.t0);
  return p;
}

std::vector<ShaderSource> Session::to_compile(PreparedReload& p, int* passes) const {
  std::vector<ShaderSource> out;
  *passes = 0;
  if (!p.result.ok) return out;
  const std::string vs = fullscreen_vertex_source();
  for (const PassSource& ps : p.passes)
    if (!cache_.contains(vs, ps.source)) out.push_back(ps.source);
  *passes = static_cast<int>(out.size());
  if (out.empty()) return out;  // nothing new to draw: post and bloom compile in line, if at all
  out.push_back(p.post_src);  // the warm-up's post pass (compile_worker.h)
  for (const ShaderSource& b : p.bloom_src)
    if (!cache_.contains(vs, b)) out.push_back(b);
  p.compiling = out;
  return out;
}

ReloadResult Session::adopt(PreparedReload p, const std::vector<std::shared_ptr<const Program>>& compiled,
                            std::exception_ptr error, double gl_ms) {
  ReloadResult r = p.result;
  if (!r.ok) {
    r.compile_ms = ms_since(p.t0);
    return r;
  }
  r.ok = false;
  try {
    if (error) std::rethrow_exception(error);
    for (size_t i = 0; i < compiled.size() && i < p.compiling.size(); ++i)
      cache_.put(fullscreen_vertex_source(), p.compiling[i], compiled[i]);
    const auto t_gl = Clock::now();
    const long misses = cache_.misses();
    auto graph = std::make_shared<PassGraph>(p.passes, &cache_);
    auto post = cache_.get(fullscreen_vertex_source(), p.post_src);
    std::unique_ptr<BloomStage> bloom_stage;
    if (!p.bloom_src.empty())
      bloom_stage = std::make_unique<BloomStage>(scene_.bloom, cache_.get(fullscreen_vertex_source(), p.bloom_src[0]),
                                                 cache_.get(fullscreen_vertex_source(), p.bloom_src[1]));
    r.compiled += static_cast<int>(compiled.size() + (cache_.misses() - misses));
    std::shared_ptr<GraphField> field = adopt_field(p, r);
    r.gl_ms = gl_ms + ms_since(t_gl);
    std::vector<std::string> warnings = std::move(p.warnings);
    for (const std::string& u : graph->unbound_sampled()) warnings.push_back(u + " is sampled but nothing is bound to it");
    if (graph_) graph->adopt_buffers(*graph_);  // buffers evolve on across a reload of a pass
    graph_ = std::move(graph);
    audio_.reset();  // the first music input plays in the window (live/audio_out.h)
    for (const PassSource& ps : p.passes)
      for (const GraphInput& in : ps.inputs)
        if (in.audio && !audio_) audio_ = in.audio;
    post_ = std::move(post);
    bloom_ = std::move(bloom_stage);
    field_ = std::move(field);
    if (!p.keep_field) {
      shape_graph_ = p.graph_of;
      shape_ = p.graph;
      shape_opts_ = p.graph_opts;
      posed_.reset();  // a new field holds the file's pose
    }
    if (p.prune) {
      prune_ = p.prune;
      prune_text_ = p.graph->prune_src.text;
    }
    warnings_ = std::move(warnings);
    std::vector<SceneParam> params = parse_scene_params(p.passes.back().source.text);
    carry_over_values(params, params_);
    params_ = std::move(params);
    compiled_debug_view_ = p.view;
    fused_ = p.fused;
    ++generation_;
    error_.clear();
    error_log_.clear();
    error_file_.clear();
    r.ok = true;
  } catch (const Error& e) {
    fail(e, r);
  }
  r.compile_ms = ms_since(p.t0);
  return r;
}

// A graph read anew gets a new shape and field; a rebuild of the same graph
// (a toggle, a debug view, a panel value) keeps the ones it has.
void Session::prepare_graph(AssembleOptions& opts, PreparedReload& p) const {
  if (!scene_.graph) return;
  if (animates_graph(scene_)) {
    // As render does (pipeline/prepare.cpp): interpreted, so that a frame's
    // pose uploads values and compiles nothing, its moving box in uniforms.
    if (opts.graph_eval == GraphEval::inline_)
      fail_input("--graph-eval inline cannot animate graph nodes: it compiles their values in",
                 scene_.file.string(), 0, "--graph-eval", "leave it auto (an animated graph is interpreted) or give interpreter");
    opts.graph_eval = GraphEval::interpreter;
    opts.bounds_uniforms = true;
  }
  if (shape_ && shape_graph_ == scene_.graph) {
    p.keep_field = true;
    opts.graph = shape_;
    return;
  }
  prepare_graph_shape(scene_, opts);
  p.graph_of = scene_.graph;
  p.graph = opts.graph;
  p.graph_opts = opts;
}

bool Session::pose_graph(double time) {
  if (!field_ || !shape_ || !animates_graph(scene_)) return false;
  if (posed_ && posed_->time == time && posed_->ok) return true;
  if (posed_ && posed_->time == time) return false;  // refused at this time already: the file's pose stands
  const auto t0 = Clock::now();
  Posed now{time, false, 0.0};
  std::shared_ptr<GraphField> field;
  try {
    Scene scene = scene_;
    pose_graph_at(scene, time);  // throws where a value breaks the graph, as render would
    const GraphParts shape = graph_parts(scene, shape_opts_);
    if (field_->repose(shape)) {
      field = field_;  // the same grid: only where a node moved is pruned again
    } else {
      const bool same = shape.prune_src.text == prune_text_;
      field = std::make_shared<GraphField>(shape, same ? prune_ : nullptr);
      if (!same && field->prune()) {
        prune_ = field->prune();
        prune_text_ = shape.prune_src.text;
      }
    }
    now.ok = true;
  } catch (const Error&) {
    // Drawn at the file's pose instead: the field that matches it.
    field = field_->repose(*shape_) ? field_ : std::make_shared<GraphField>(*shape_, prune_);
  }
  field_ = std::move(field);
  now.ms = ms_since(t0);
  posed_ = now;
  return now.ok;
}

// The field the adopted programs read: the worker's, one built here (its
// pruning pass compiled only when its text is new), the current one, or none.
std::shared_ptr<GraphField> Session::adopt_field(PreparedReload& p, ReloadResult& r) {
  if (p.keep_field) return field_;
  if (!p.graph || !p.graph->plan.interpret) return nullptr;
  r.graph = true;
  std::shared_ptr<GraphField> field = std::move(p.field);
  if (field && p.prune) ++r.compiled;  // the worker's
  if (!field) {
    const std::string& text = p.graph->prune_src.text;
    if (!p.prune && !text.empty()) {
      if (prune_ && text == prune_text_) p.prune = prune_;
      else ++r.compiled;  // GraphField compiles it
    }
    field = std::make_shared<GraphField>(*p.graph, p.prune);
    p.prune = field->prune();
  }
  if (p.graph->plan.pruned()) r.prune_ms = field->build_ms();
  return field;
}

void Session::fail(const Error& e, ReloadResult& r) {
  error_ = shown_error(e.info());
  error_log_ = e.info().detail;
  error_file_ = e.info().file;
  r.ok = false;
  r.error = error_;
  r.log = error_log_;
}

bool Session::features_changed() const {
  // Lights and patterns cannot change in the panel, and a GLSL edit reloads
  // anyway: the library names of the current program still hold.
  return specialized_ && graph_ && derive_features(scene_, features_.library) != features_;
}

std::vector<fs::path> Session::scene_files() const {
  std::vector<fs::path> out{scene_.file};
  if (scene_.graph && scene_.graph->file != scene_.file) out.push_back(scene_.graph->file);
  return out;
}

std::vector<fs::path> Session::watched_files() const {
  std::vector<fs::path> out;
  if (!scene_.file.empty()) out.push_back(scene_.file);
  if (!scene_.shadertoy_file.empty()) out.push_back(scene_.shadertoy_file);
  if (!scene_.map_file.empty()) out.push_back(scene_.map_file);
  if (scene_.graph && scene_.graph->file != scene_.file) out.push_back(scene_.graph->file);
  out.insert(out.end(), deps_.begin(), deps_.end());
  if (!error_file_.empty()) {
    std::error_code ec;
    if (fs::exists(error_file_, ec) || fs::exists(fs::path(error_file_).parent_path(), ec))
      out.push_back(error_file_);
  }
  return out;
}

}  // namespace ms::live
