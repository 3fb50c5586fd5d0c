#include "live/session.h"

#include <chrono>

#include "core/error.h"
#include "render/environment.h"
#include "render/project_passes.h"
#include "scene/quality.h"
#include "shader/shadertoy.h"

namespace ms::live {
namespace fs = std::filesystem;

namespace {

bool same_camera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up && a.fov_deg == b.fov_deg;
}

}  // namespace

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

ReloadResult Session::reload(bool from_disk) {
  ReloadResult r;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    if (from_disk || !disk_ok_) {
      Scene fresh;
      try {
        fresh = opts_.load();
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
    // The same passes `render` builds (cli/input.cpp): a scene's one pass,
    // or a Shadertoy shader's buffers and Image pass, media found.
    std::vector<PassSource> passes;
    std::vector<std::string> warnings;
    if (shadertoy()) {
      const fs::path wrapper = has_toml() ? scene_.file : fs::path{};
      const ShaderProject project =
          scene_.passes ? *scene_.passes : load_shadertoy_file(scene_.shadertoy_file, opts, wrapper);
      passes = shadertoy_passes(project, scene_.shadertoy, opts, wrapper, warnings);
    } else {
      PassSource pass;
      pass.name = scene_.name;
      pass.source = assemble_scene(scene_, opts);
      attach_environment(scene_, pass);  // [sky] environment (render/environment.h)
      passes.push_back(std::move(pass));
    }
    deps_.clear();  // preprocessing worked: these are the files now
    for (const PassSource& p : passes) deps_.insert(deps_.end(), p.source.dependencies.begin(), p.source.dependencies.end());
    const ShaderSource& main_src = passes.back().source;
    // A debug view shows values, not radiance: its post pass stores them as
    // they are (no tone map, no sRGB encode; exposure 1, display_exposure()).
    const bool bloom = scene_.bloom.enabled && !shadertoy() && view == 0;  // docs/post.md
    const ShaderSource post_src =
        assemble_post(scene_.render.tonemap, !shadertoy() && view == 0, opts_.assemble, shadertoy(), bloom);
    r.cached = cache_.contains(fullscreen_vertex_source(), main_src);
    const auto t_gl = std::chrono::steady_clock::now();
    r.assemble_ms = std::chrono::duration<double, std::milli>(t_gl - t0).count();
    auto graph = std::make_shared<PassGraph>(passes, &cache_);
    auto post = cache_.get(fullscreen_vertex_source(), post_src);
    std::unique_ptr<BloomStage> bloom_stage;
    if (bloom)
      bloom_stage = std::make_unique<BloomStage>(scene_.bloom,
                                                 cache_.get(fullscreen_vertex_source(), assemble_bloom(false, opts_.assemble)),
                                                 cache_.get(fullscreen_vertex_source(), assemble_bloom(true, opts_.assemble)));
    r.gl_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_gl).count();
    for (const std::string& u : graph->unbound_sampled()) warnings.push_back(u + " is sampled but nothing is bound to it");
    if (graph_) graph->adopt_buffers(*graph_);  // buffers evolve on across a reload of a pass
    graph_ = std::move(graph);
    audio_.reset();  // the first music input plays in the window (live/audio_out.h)
    for (const PassSource& p : passes)
      for (const GraphInput& in : p.inputs)
        if (in.audio && !audio_) audio_ = in.audio;
    post_ = std::move(post);
    bloom_ = std::move(bloom_stage);
    warnings_ = std::move(warnings);
    std::vector<SceneParam> params = parse_scene_params(main_src.text);
    carry_over_values(params, params_);
    params_ = std::move(params);
    compiled_debug_view_ = view;
    ++generation_;
    error_.clear();
    error_log_.clear();
    error_file_.clear();
    r.ok = true;
  } catch (const Error& e) {
    error_ = format_error(e.info());
    error_log_ = e.info().detail;
    error_file_ = e.info().file;
    r.error = error_;
    r.log = error_log_;
  }
  r.compile_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

bool Session::features_changed() const {
  // Lights and patterns cannot change in the panel, and a GLSL edit reloads
  // anyway: the library names of the current program still hold.
  return specialized_ && graph_ && derive_features(scene_, features_.library) != features_;
}

std::vector<fs::path> Session::watched_files() const {
  std::vector<fs::path> out;
  if (!scene_.file.empty()) out.push_back(scene_.file);
  if (!scene_.shadertoy_file.empty()) out.push_back(scene_.shadertoy_file);
  if (!scene_.map_file.empty()) out.push_back(scene_.map_file);
  out.insert(out.end(), deps_.begin(), deps_.end());
  if (!error_file_.empty()) {
    std::error_code ec;
    if (fs::exists(error_file_, ec) || fs::exists(fs::path(error_file_).parent_path(), ec))
      out.push_back(error_file_);
  }
  return out;
}

}  // namespace ms::live
