// What the viewer shows, and how it gets rebuilt: the scene (as last read
// from disk and as edited in the panel), the pass graph and post program
// (the last GOOD ones: a failed reload keeps them; a good one keeps the
// buffers' state), the scene's own parameters, and the files to watch.
// Loading and assembly are the frame pipeline's, as `render`'s
// (pipeline/input.h); only the compiled programs are kept here. Needs the GL context current for reload().
#pragma once
#include <chrono>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "live/live_values.h"
#include "live/param_reload.h"
#include "render/bloom.h"
#include "render/graph.h"
#include "render/graph_field.h"
#include "render/program.h"
#include "render/program_cache.h"
#include "scene/features.h"
#include "scene/overrides.h"
#include "scene/scene.h"
#include "shader/assemble.h"

namespace ms::live {

struct SessionOptions {
  std::filesystem::path input;  // the .toml scene or Shadertoy .glsl, read from disk on each save
  SceneOverrides set;           // --set, applied to every read: a save keeps the overrides
  AssembleOptions assemble;     // the shader dir; DEBUG_VIEW is added per reload
};

struct ReloadResult {
  bool ok = false;
  std::string error;           // "file:line: message (hint)" when !ok
  std::string log;             // when !ok: the compiler's whole log, mapped to file:line (what "+N more" stands for)
  bool camera_changed = false; // the file's [camera] differs from the previous read
  double compile_ms = 0.0;     // load + assemble + compile + link
  double assemble_ms = 0.0;    // of which ours: reading the files, preprocessing and assembly
  double gl_ms = 0.0;          // of which the driver's: compile and link (llvmpipe JITs later, at the first draw)
  bool cached = false;         // the main program came from the cache: nothing compiled
  // An interpreted graph scene's field was rebuilt (new buffers, pruned
  // again): `compiled` programs went into this build, the worker's and
  // those compiled in line; `prune_ms` the pruning pass, < 0 with no grid.
  bool graph = false;
  int compiled = 0;
  double prune_ms = -1.0;
};

// The line the viewer shows for an error: its whole log follows it (on
// stderr and in the error box), so the hint points there, not to -v.
std::string shown_error(ErrorInfo e);

class Session {
 public:
  explicit Session(SessionOptions opts) : opts_(std::move(opts)) {}

  // from_disk: read the input again (the TOML changed); otherwise rebuild
  // the current, possibly edited scene (a GLSL file, a toggle or the debug
  // view changed). While the last disk read failed every reload reads the
  // disk. Never throws for bad input: the error is in the result and in
  // error(), and the last good programs stay.
  ReloadResult reload(bool from_disk) {
    PreparedReload p = prepare(from_disk);
    return adopt(std::move(p), {}, nullptr, 0.0);
  }

  // reload() in halves, for the viewer's compile worker (live/compile_worker.h).
  // prepare() reads and assembles (the scene, the watched files and a read
  // or assembly error apply at once; the programs stay); to_compile() lists
  // the fragment sources the cache lacks (passes first, then the post
  // pass, then bloom's); adopt() keeps `compiled` (one per to_compile()
  // source, linked on a context sharing this one's objects) or reports
  // `error` (a compile error thrown there) as reload() would, and swaps
  // the programs in. A PreparedReload not adopted changes no programs.
  struct PreparedReload {
    ReloadResult result;  // !result.ok: preparing failed, adopt() returns it
    std::chrono::steady_clock::time_point t0;
    std::vector<PassSource> passes;
    std::vector<std::string> warnings;
    ShaderSource post_src;
    std::vector<ShaderSource> bloom_src;  // empty without bloom
    int view = 0;
    bool fused = false;  // the one-pass frame (fuse_frame())
    std::vector<ShaderSource> compiling;  // what to_compile() listed: adopt()'s `compiled` match these
    // A graph read anew (a rebuild of the same one keeps its shape and
    // field): its prepared shape, the one the passes were assembled from,
    // and, interpreted, the field the worker built from it, if it did
    // (live/compile_worker.h); else adopt() builds it, compiling the
    // pruning pass when it is new.
    std::shared_ptr<const SceneGraph> graph_of;
    std::shared_ptr<const GraphParts> graph;
    std::shared_ptr<const Program> prune;
    std::shared_ptr<GraphField> field;
    AssembleOptions graph_opts;  // what `graph` was derived with: a pose derives it again so
    bool keep_field = false;
  };
  PreparedReload prepare(bool from_disk);
  std::vector<ShaderSource> to_compile(PreparedReload& p, int* passes) const;
  ReloadResult adopt(PreparedReload p, const std::vector<std::shared_ptr<const Program>>& compiled,
                     std::exception_ptr error, double gl_ms);

  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  const Scene& file_scene() const { return file_scene_; }  // writeback diffs against it
  bool shadertoy() const { return !scene_.shadertoy_file.empty() || scene_.passes != nullptr; }
  bool has_toml() const { return scene_.file.extension() == ".toml"; }
  // The last good build binds Shadertoy's keyboard texture to some pass.
  bool reads_keyboard() const;
  // Files read with the scene itself (the TOML, its graph's JSON): a save
  // of one is a reload(true).
  std::vector<std::filesystem::path> scene_files() const;

  // True when the scene as edited in the panel needs other shader code than
  // the current program has (a reflectivity dragged from or to 0 adds or
  // drops the reflection loop of a specialized shader): reload(false) then.
  bool features_changed() const;
  // The panel values the next builds keep as uniforms, folded otherwise
  // (live/live_values.h decides which).
  void set_live(std::vector<std::string> live) { opts_.assemble.live = std::move(live); }
  const std::vector<std::string>& live() const { return opts_.assemble.live; }
  // The accumulation target the next builds are for (ViewState::accumulate):
  // with none, they compile render's one-pass frame (fuse_frame()).
  // fused(): the current program is that one (FrameParams::fused_post).
  void set_accumulate(int accumulate) { accumulate_ = accumulate; }
  bool fuse_wanted() const { return fuse_frame(scene_, accumulate_, shadertoy() ? 0 : debug_view, shadertoy()); }
  bool fused() const { return fused_; }

  // An interpreted graph scene's node buffers and pruned grid, bound
  // before every draw of the scene pass; null otherwise.
  std::shared_ptr<const GraphField> field() const { return field_; }
  // An animated graph's field at `time`: its nodes posed by the scene's
  // graph tracks, the grid pruned again when the time moved (the pruning
  // pass reused, nothing else compiled). False when the graph does not
  // animate, or a value at `time` breaks it: the field then holds the
  // file's pose, and so must the frame. pose_ms(): the last pose's time.
  bool pose_graph(double time);
  double pose_ms() const { return posed_ ? posed_->ms : 0.0; }
  // The graph to draw (null before the first good build) and its post pass.
  PassGraph* graph() const { return graph_.get(); }
  const Program* main_program() const { return graph_ ? &graph_->program(graph_->size() - 1) : nullptr; }
  const Program* post_program() const { return post_.get(); }
  // The scene's [post.bloom] stage (render/bloom.h) for FrameParams::bloom;
  // nullptr without it, for a Shadertoy shader and in a debug view.
  BloomStage* bloom() const { return bloom_.get(); }
  // Warnings of the last good build (missing media stood in for, unbound channels).
  const std::vector<std::string>& warnings() const { return warnings_; }
  int generation() const { return generation_; }  // +1 per successful reload
  // The clip of the program's first music input, or null (live/audio_out.h plays it).
  const std::shared_ptr<const AudioClip>& audio() const { return audio_; }
  const std::string& error() const { return error_; }
  // The whole mapped compiler log of the last failed build (empty when it
  // failed before compiling, or did not fail): the panel shows it.
  const std::string& error_log() const { return error_log_; }

  // A preset of scene/quality.h, re-based on the file's [quality] exactly as
  // `render --preset` does (its explicit keys kept); toggles survive a
  // preset change. Empty: the file's own preset. Applies at once when the
  // file is loaded, else at the first reload.
  void set_preset(const std::string& name);
  // The preset in use: the one set, else the file's (default "balanced").
  const std::string& preset() const { return preset_.empty() ? file_scene_.quality.preset : preset_; }
  // DEBUG_VIEW compiled into the current program (0 = lit), and the one to use next.
  int compiled_debug_view() const { return compiled_debug_view_; }
  // The exposure the post pass is given: the scene's, or 1 in a debug view,
  // whose values are stored as they are (0.5 N + 0.5 as bytes).
  float display_exposure() const { return compiled_debug_view_ > 0 ? 1.0f : scene_.render.exposure; }
  int debug_view = 0;

  // Delete the GL programs now, while the context is still current (the
  // viewer calls this before the window goes).
  void release_gl() {
    field_.reset();
    prune_.reset();
    graph_.reset();
    post_.reset();
    bloom_.reset();
    cache_.clear();
  }

  std::vector<SceneParam>& params() { return params_; }
  // The scene file, its graph's JSON, every file the last successful
  // preprocess read, and the file named by the last error.
  std::vector<std::filesystem::path> watched_files() const;

 private:
  void fail(const Error& e, ReloadResult& r);
  void prepare_graph(AssembleOptions& opts, PreparedReload& p) const;
  std::shared_ptr<GraphField> adopt_field(PreparedReload& p, ReloadResult& r);
  SessionOptions opts_;
  Scene scene_, file_scene_;
  bool disk_ok_ = false;
  std::string preset_;  // empty: the file's
  std::shared_ptr<PassGraph> graph_;
  std::shared_ptr<const AudioClip> audio_;
  std::shared_ptr<const Program> post_;
  std::unique_ptr<BloomStage> bloom_;  // with post_: its post pass was assembled with BLOOM 1
  std::shared_ptr<GraphField> field_;
  std::shared_ptr<const SceneGraph> shape_graph_;  // what shape_ (and field_) were made from
  std::shared_ptr<const GraphParts> shape_;
  AssembleOptions shape_opts_;  // what shape_ was derived with
  struct Posed {
    double time = 0.0;
    bool ok = false;  // false: the pose was refused, field_ holds the file's
    double ms = 0.0;
  };
  std::optional<Posed> posed_;  // where field_ stands, when an animated graph was posed
  std::shared_ptr<const Program> prune_;  // the last pruning pass, kept by its text: a move reuses it
  std::string prune_text_;
  std::vector<std::string> warnings_;
  ProgramCache cache_;     // every program built, by source hash: a toggle seen before is not recompiled
  bool specialized_ = false;
  FeatureSet features_;    // of the last program built or tried, when specialized
  int generation_ = 0;
  int compiled_debug_view_ = 0;
  int accumulate_ = -1;  // set_accumulate()
  bool fused_ = false;
  std::string error_, error_log_, error_file_;
  std::vector<std::filesystem::path> deps_;
  std::vector<SceneParam> params_;
};

}  // namespace ms::live
