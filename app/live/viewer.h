// `marchstudio view`: a GLFW window that renders the scene continuously with
// the same assembly, programs and FrameRenderer as `render`, reloads on
// every save of the scene or any file it includes (inotify), and keeps the
// last good frame on errors. The loop lives in viewer.cpp; camera, watcher,
// panel, overlay and input each have their own file.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "live/compute_trace.h"
#include "live/live_values.h"
#include "live/recording.h"
#include "scene/overrides.h"
#include "scene/scene.h"
#include "shader/assemble.h"

namespace ms::live {

struct ViewerOptions {
  std::filesystem::path input;       // .toml or Shadertoy .glsl, read on every save
  SceneOverrides set;                // --set, applied to every read of the input (pipeline/input.h)
  AssembleOptions assemble;          // the shader dir
  int width = 0, height = 0;         // window size; 0: the scene's, at most 1280x720
  int debug_view = 0;                // DEBUG_VIEW at start (0 = lit)
  int accumulate = -1;               // samples to accumulate while nothing changes: -1 the scene's spp, 0 no limit, N
  std::string preset;                // a quality preset at start (scene/quality.h); empty: the file's
  bool paused = false;
  std::optional<double> time;        // start time; none: the scene's [render] time
  std::filesystem::path log_file;    // empty: log lines go to stderr
  std::filesystem::path capture_dir; // empty: no captures
  std::filesystem::path shot_dir = ".";
  int shot_width = 0, shot_height = 0;  // 0: screenshots at the window's render size
  long shot_frame = -1;              // take both screenshots after this frame (scripts, docs)
  double exit_after = 0.0;           // seconds; 0: run until closed
  long max_frames = 0;               // 0: no limit
  int debounce_ms = 10;              // quiet time that ends a save (editors write in steps)
  bool hide_panel = false;
  RecordOptions record;              // F9 and --record (live/recording.h)
  ScriptedDrag drag;                 // --drag: a panel drag, scripted (live/live_values.h)
  std::string audio_device = "default";  // ALSA PCM for a music input; "none": silent (live/audio_out.h)
  DispatchOptions dispatch;          // --dispatch: what traces the scene pass (live/compute_trace.h)
  // M's and --mesh-on-exit's exports (live/mesh_export.h).
  std::filesystem::path mesh_on_exit;  // empty: none
  int mesh_resolution = 256;           // cells along the box's longest side
  long mesh_frame = -1;                // export as M does after settled frame N (scripts)
};

// Runs until the window closes, Esc, --exit-after or --max-frames, then
// waits for a mesh export in flight and writes --mesh-on-exit. Returns the
// process exit code: 3 when --mesh-on-exit's export failed. Throws ms::Error only before the window is up (no
// display, bad flags); later problems are shown and logged, never fatal.
int run_viewer(const ViewerOptions& opts);

}  // namespace ms::live
