// `marchstudio view`: the live viewer (app/live/) with hot reload, for a
// scene (.toml) or a Shadertoy shader (.glsl). docs/viewer.md.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/load_flags.h"
#include "live/live_values.h"
#include "io/sequence.h"
#include "pipeline/input.h"
#include "render/compute_frame.h"
#include "shader/compute_wrap.h"

namespace CLI {
class App;
}

namespace ms {

// --drag TARGET=V@A..B as read: its target, values and frames. Whether
// the target exists and takes that many values is checked against the
// scene when the viewer starts.
struct DragFlag {
  std::string text;            // as given, for the messages of that check
  live::ScriptedDrag drag;     // target and frames; `to` set from `values` by the check
  std::vector<double> values;  // x, or x,y,z (a uniform: its components)
};
// Throws bad_input naming --drag for anything but TARGET=V@A..B with A <= B.
DragFlag parse_drag_flag(const std::string& text);

struct ViewArgs {
  std::string input;
  ImageSize size;            // window --size WxH; 0x0: the scene's, at most 1280x720
  LoadFlags load;            // no --disable or Shadertoy options; --set and --uniform apply again at every reload
  int debug_view = 0;
  int accumulate = -1;
  std::string record_dir, record_video;       // --record-dir, --record-video
  std::optional<FrameRange> record_frames;   // --record A..B
  double record_fps = 0.0;
  std::string audio_device = "default";  // --accumulate: -1 the scene's spp, 0 no limit (unlimited), N
  std::optional<double> time;  // none: the scene's [render] time
  bool paused = false;
  std::string log;           // --log FILE; empty: stderr
  std::string capture_dir;
  std::string shot_dir = ".";
  ImageSize shot_size;       // --shot-size WxH; 0x0: the window's
  long shot_frame = -1;
  std::optional<DragFlag> drag;  // --drag TARGET=V@A..B (scripts): a panel drag
  double exit_after = 0.0;
  long max_frames = 0;
  int debounce_ms = 10;
  bool no_panel = false;
  Dispatch dispatch = Dispatch::fragment;     // --dispatch fragment|compute|auto
  std::optional<ComputeGroup> compute_group;  // hidden --compute-group WxH; none: 8x8, or auto's measured group
  bool verbose = false;        // -v: every compile error of a load that fails before the window
  std::string mesh_on_exit;  // --mesh-on-exit FILE; empty: none
  int mesh_resolution = 256;  // --mesh-resolution: M's and --mesh-on-exit's cells
  long mesh_frame = -1;      // --mesh-frame N (scripts): M after settled frame N
};

CLI::App* add_view_command(CLI::App& app, ViewArgs& args);
int run_view(const ViewArgs& args);

}  // namespace ms
