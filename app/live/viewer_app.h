// The viewer's window loop, shared by its two halves: live/viewer.cpp (the
// loop, frames, screenshots, the panel's writes) and live/viewer_build.cpp
// (reloads and rebuilds: what changed, the compile worker, adoption, the
// log lines). Internal to live/; run_viewer() (live/viewer.h) is the entry.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "live/audio_out.h"
#include "live/compile_worker.h"
#include "live/live_log.h"
#include "live/live_values.h"
#include "live/mesh_export.h"
#include "live/recording.h"
#include "live/session.h"
#include "live/view_state.h"
#include "live/viewer.h"
#include "live/viewer_frame.h"
#include "live/watcher.h"
#include "render/program_cache.h"

struct GLFWwindow;

namespace ms::live {

std::string fmt(const char* f, double v);  // printf of one number, for log lines

// A reload in flight: seen at `t_event`, logged once its first frame is drawn.
struct PendingReload {
  bool active = false;
  int number = 0;
  double t_event = 0.0;
  long frame_at_event = 0, iteration_at_event = 0;
  ReloadResult result;
  double first_draw_ms = 0.0;  // the first frame with the new program, waited for: llvmpipe JITs it here
  double warm_ms = 0.0;        // the worker's warm-up draws (live/compile_worker.h)
  long frames_during_compile = 0;  // frames drawn with the old program while the worker compiled
};

// What a build is for, which decides its log line: a file changed (a
// numbered reload), a toggle, preset or debug view (rebuild), or a panel
// value folded or made live (values).
enum class BuildKind { reload, rebuild, values };

// A build whose programs the worker is compiling; the last good ones draw meanwhile.
struct Compiling {
  bool active = false;
  BuildKind kind = BuildKind::reload;
  int number = 0;  // a reload's number (frame_N.png); the others have none
  double t_event = 0.0;
  long frame_at_event = 0, iteration_at_event = 0, frames_at_submit = 0;
  long settled_at_submit = 0;  // Viewer::settled_ when it started
  Session::PreparedReload plan;
  std::string compute_text;  // the compute source the worker compiles with it; empty: none
};

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& o)
      : o_(o), log_(o.log_file), session_(SessionOptions{o.input, o.set, o.assemble}), drag_(o.drag), recorder_(o.record) {}
  int run();
  // After run(): waits for M's export in flight, then writes --mesh-on-exit;
  // `code` (run()'s), or 3 when that export failed (live/viewer_mesh.cpp).
  int finish_mesh(int code);

 private:
  // wait: block until the programs are built (the first build: nothing to show before it).
  void reload(bool from_disk, double t_event, long frame_at_event, long iteration_at_event, bool wait = false);
  void build(Compiling c, bool wait);
  void adopt_compiled(bool wait = false);
  void finish_build(const Compiling& c, const ReloadResult& r, double warm_ms);
  void finish_reload(const Compiling& c, const ReloadResult& r, double warm_ms);
  void report_failure(const ReloadResult& r);
  void rebuild_values(std::vector<std::string> live);
  void start_rebuild(BuildKind kind);
  void poll_files();
  void after_frame();
  void serve_requests();
  void screenshot();
  void write_camera();
  void write_values();
  void watch_bounds(double now);
  MeshExportSpec mesh_spec(const std::filesystem::path& output);
  void start_mesh();
  void poll_mesh();
  void report_mesh(const MeshExportResult& r);

  const ViewerOptions& o_;
  LiveLog log_;
  Session session_;
  ViewState s_;
  Watcher watcher_;
  GLFWwindow* window_ = nullptr;
  FrameDrawer* drawer_ = nullptr;
  long frames_ = 0, iterations_ = 0;
  // Frames drawn with no build in flight: --drag and --shot-frame count
  // these, so a script does not depend on how long a compile takes.
  long settled_ = 0;
  int reloads_ = 0, jobs_ = 0;
  PendingReload pending_;
  LiveValues live_;     // what the program folds, and when a panel edit rebuilds it
  ScriptedDrag drag_;   // --drag
  std::unique_ptr<CompileWorker> worker_;  // null: compile on this thread (no shared context)
  Compiling compiling_;
  int compiling_job_ = 0;  // its worker job id
  Recorder recorder_;
  AudioOut audio_;
  const AudioClip* audio_clip_ = nullptr;  // what audio_ was opened for
  // The bounds check (render/bounds_check.h): after each reload, when a
  // slider moves, and once a second for animation; reported when it changes.
  ProgramCache bounds_cache_{2};
  int bounds_generation_ = -1;
  std::vector<SceneParam> bounds_params_;
  double t_bounds_ = 0.0;
  std::string bounds_warning_;
  MeshExport mesh_;                         // M's export, polled each frame
  std::optional<MeshExportSpec> exit_mesh_;  // --mesh-on-exit's, taken as the loop ends
};

}  // namespace ms::live
