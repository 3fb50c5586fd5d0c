// The viewer's builds (live/viewer_app.h): a saved file's reload, a
// toggle's rebuild and a panel value's, all through the compile worker.
#include <algorithm>

#include "live/viewer_app.h"

#include "core/clock.h"
#include "core/error.h"
#include "render/compute_frame.h"

namespace ms::live {
namespace fs = std::filesystem;

void Viewer::reload(bool from_disk, double t_event, long frame_at_event, long iteration_at_event, bool wait) {
  Compiling c{true, BuildKind::reload, reloads_++, t_event, frame_at_event, iteration_at_event, frames_, settled_,
              session_.prepare(from_disk), {}};
  if (c.plan.result.camera_changed) s_.camera = s_.scene_camera = session_.scene().camera;
  build(std::move(c), wait);
}

// Every build goes through the worker: a reload, a toggle's rebuild and a
// panel value's. The newest replaces one in flight (the worker drops it).
void Viewer::build(Compiling c, bool wait) {
  live_.built(session_.scene(), session_.live());
  if (compiling_.active && c.kind == BuildKind::reload)  // only the newest save is adopted
    log_.line(compiling_.kind == BuildKind::reload
                  ? "reload superseded " + std::to_string(compiling_.number) + " by " + std::to_string(c.number)
                  : "reload supersedes a rebuild");
  compiling_.active = false;
  // New includes are watched from now on, removed ones dropped.
  watcher_.watch(session_.watched_files());
  int passes = 0;
  std::vector<ShaderSource> sources = session_.to_compile(c.plan, &passes);
  if (!worker_ || sources.empty()) {  // nothing to compile, or no worker: in line
    const ReloadResult r = session_.adopt(std::move(c.plan), {}, nullptr, 0.0);
    return finish_build(c, r, 0.0);
  }
  CompileJob job{++jobs_, std::move(sources), passes, !c.plan.fused, std::nullopt, {}, c.plan.graph,
                 c.plan.keep_field ? session_.field() : nullptr};
  // Traced with compute: the worker compiles that program too (docs/viewer.md#compute).
  // A pass compute refuses goes without: the UI thread's update() says why.
  if (c.plan.result.ok && !c.plan.passes.empty()) {
    try {
      if (drawer_) {
        job.compute_group = drawer_->compute_group();
        ShaderSource cs = compute_source(c.plan.passes.back(), job.compute_group);
        if (drawer_->wants_compute(cs)) job.compute = std::move(cs);
      }
    } catch (const Error&) {
    }
  }
  c.compute_text = job.compute ? job.compute->text : std::string();
  worker_->submit(std::move(job));
  if (c.kind == BuildKind::reload) log_.line("reload compiling " + std::to_string(c.number));
  compiling_ = std::move(c);
  compiling_job_ = jobs_;
  if (wait) adopt_compiled(true);
}

// Each loop iteration: the worker's result, when it is the newest build's.
void Viewer::adopt_compiled(bool wait) {
  if (!compiling_.active) return;
  std::optional<CompileResult> got;
  if (wait) got = worker_->wait(compiling_job_);
  else got = worker_->poll();
  if (!got || got->id != compiling_job_) return;
  compiling_.active = false;
  compiling_.plan.field = std::move(got->field);  // built with the programs (live/compile_worker.h)
  compiling_.plan.prune = std::move(got->prune);
  const ReloadResult r = session_.adopt(std::move(compiling_.plan), got->programs, got->error, got->gl_ms);
  if (r.ok && !compiling_.compute_text.empty())  // taken by the drawer's next update() (the program line's)
    drawer_->offer_compute(std::move(compiling_.compute_text), std::move(got->compute), std::move(got->compute_error));
  finish_build(compiling_, r, got->warm_ms);
}

void Viewer::finish_build(const Compiling& c, const ReloadResult& r, double warm_ms) {
  if (c.kind == BuildKind::reload) return finish_reload(c, r, warm_ms);
  const std::string during = " frames_during_compile=" + std::to_string(frames_ - c.frames_at_submit);
  const std::string ms = " compile_ms=" + fmt("%.1f", r.compile_ms) + (r.cached ? " cached" : "");
  if (c.kind == BuildKind::rebuild) {
    log_.line(std::string("rebuild ") + (r.ok ? "ok" : "failed") + " debug_view=" +
              std::to_string(session_.compiled_debug_view()) + ms + during + (r.ok ? "" : " -- " + r.error));
  } else {
    const PassGraph* g = session_.graph();
    log_.line(std::string("values ") + (r.ok ? "ok" : "failed") + " live=" + live_names(session_.live()) +
              " uniforms=" + (g ? uniform_tables(g->pass(g->size() - 1).source.text) : "none") +
              " fused=" + (session_.fused() ? "1" : "0") + " frame=" + std::to_string(c.settled_at_submit) + ms +
              during + (r.ok ? "" : " -- " + r.error));
  }
  if (!r.ok) report_failure(r);
}

void Viewer::finish_reload(const Compiling& c, const ReloadResult& r, double warm_ms) {
  pending_ = {true, c.number, c.t_event, c.frame_at_event, c.iteration_at_event, r, 0.0, warm_ms,
              frames_ - c.frames_at_submit};
  // While broken, any source-like file next to the watched ones counts.
  watcher_.watch(session_.watched_files());
  watcher_.set_match_any(!r.ok);
  if (!r.ok) report_failure(r);
  s_.shader_keys = session_.reads_keyboard();  // letters are the viewer's unless the shader reads them
  if (r.ok)  // docs/viewer.md#folding, #compute
    log_.line(std::string("program fused=") + (session_.fused() ? "1" : "0") + " dispatch=" + drawer_->dispatch());
  if (r.ok && r.graph)  // docs/viewer.md#graphs: a parameter or transform saved compiles nothing
    log_.line("graph updated: " + std::to_string(r.compiled) + " programs compiled, " +
              (r.prune_ms < 0.0 ? std::string("not pruned") : "pruning " + fmt("%.1f", r.prune_ms) + " ms"));
  if (r.ok && session_.audio().get() != audio_clip_) {  // a music input came, went or changed
    audio_clip_ = session_.audio().get();
    if (!audio_clip_) {
      audio_.close();
    } else {
      const std::string why = audio_.open(o_.audio_device, session_.audio());
      log_.line(why.empty() ? "audio playing " + o_.audio_device : "audio silent -- " + why);
    }
  }
}

// The one-line error on stderr, and the compiler's whole log after it, on
// stderr and as compile_log lines in the event log (the panel shows it too).
void Viewer::report_failure(const ReloadResult& r) {
  std::fprintf(stderr, "marchstudio: %s\n", r.error.c_str());
  size_t at = 0;
  while (at < r.log.size()) {
    size_t end = r.log.find('\n', at);
    if (end == std::string::npos) end = r.log.size();
    const std::string line = r.log.substr(at, end - at);
    if (!line.empty()) {
      std::fprintf(stderr, "  %s\n", line.c_str());
      if (!log_.to_stderr()) log_.line("compile_log " + line);
    }
    at = end + 1;
  }
}

void Viewer::poll_files() {
  session_.set_accumulate(s_.accumulate);  // O, or accumulation turned off: the one-pass frame or not
  std::vector<fs::path> changed = watcher_.poll();
  if (!changed.empty()) {
    const double t_event = clock_seconds();
    watcher_.settle(changed, o_.debounce_ms, 100);
    bool from_disk = false;  // the TOML or its graph's JSON: read the scene again
    for (const fs::path& f : session_.scene_files())
      from_disk = from_disk || std::find(changed.begin(), changed.end(), fs::absolute(f).lexically_normal()) != changed.end();
    reload(from_disk, t_event, frames_, iterations_);
  } else if (s_.want_disk_reload) {
    s_.want_disk_reload = false;
    reload(true, clock_seconds(), frames_, iterations_);
  } else if (compiling_.active) {
    return;  // a toggle's rebuild waits for the reload in flight (it would be adopted over)
  } else if (s_.want_reassemble || s_.debug_view != session_.debug_view || session_.features_changed()) {
    // A toggle, preset, quality value or debug view, or a panel edit that
    // changes what the specialized shader needs: same files, new defines.
    s_.want_reassemble = false;
    session_.debug_view = s_.debug_view;
    start_rebuild(BuildKind::rebuild);
  } else if (std::optional<std::vector<std::string>> live = live_.rebuild(session_.scene(), s_.panel_dragging)) {
    rebuild_values(std::move(*live));
  } else if (session_.graph() && session_.error().empty() && session_.fuse_wanted() != session_.fused()) {
    rebuild_values(session_.live());  // accumulation turned on or off
  }
}

// A folded light, material or sky value was edited: rebuild with the
// dragged ones live (uniforms), or all folded once the drag let go. Until
// it is built the last program draws, at the values it was built with.
void Viewer::rebuild_values(std::vector<std::string> live) {
  session_.set_live(std::move(live));
  start_rebuild(BuildKind::values);
}

// The same files with new defines or live values, compiled like a reload.
void Viewer::start_rebuild(BuildKind kind) {
  const double now = clock_seconds();
  build(Compiling{true, kind, -1, now, frames_, iterations_, frames_, settled_, session_.prepare(false), {}},
        false);
}

}  // namespace ms::live
