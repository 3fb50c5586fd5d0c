// What the frame pipeline is asked to make, as typed and checked values:
// a FrameJob is one still (render, one line of a --jobs file); a
// SequenceJob adds the frames, the shard and the video. cli/ turns flags
// into these (cli/render_job.h, cli/sequence_cmd.cpp) and nothing below it
// sees a flag string: sizes, backends, dispatches and defines arrive
// parsed, AOV names and include directories checked, the shader directory
// resolved. Zero values mean "the scene's".
//
//   FrameJob job;  job.input = "scene.toml";  job.output = "scene.png";
//   job.shader_dir = resolve_shader_dir({});
//   FrameSession session;
//   render_still_job(job, session);    // pipeline/still_job.h
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/context.h"
#include "io/image.h"
#include "io/sequence.h"
#include "pipeline/input.h"
#include "render/compute_frame.h"
#include "render/tiles.h"
#include "scene/overrides.h"
#include "shader/assemble.h"
#include "shader/compute_wrap.h"
#include "shader/scene_params.h"

namespace ms {

// A scene's frame rate when neither it nor a flag says (a Shadertoy
// shader's is its [shadertoy] fps, 60): sequences' --fps default, and the
// rate a still's frame number is counted at.
inline constexpr double kSceneFps = 24.0;

struct FrameJob {
  // How a batch names this job in its errors: "jobs.jsonl:3", or the input.
  std::string label;
  std::filesystem::path input;
  std::filesystem::path output;      // a still's file (never empty); unused by a sequence
  // A still handed back here instead of written: `output` then only names
  // its format, and the image holds what that file would (io/stored_pixels.h).
  // One that would be drawn in tiles is refused. Null: written.
  Image* image_out = nullptr;
  ImageSize size;                    // 0x0: the scene's
  int spp = 0;                       // 1..1024; 0: the scene's
  std::optional<float> time;         // seconds; empty: the scene's
  std::optional<int> frame;          // uFrame / iFrame, >= 0; empty: the still's frame (still_frame_of)
  std::optional<double> fps;         // > 0; empty: the scene's (a Shadertoy shader's 60)
  Backend backend = Backend::automatic;
  std::filesystem::path shader_dir;  // resolved: holds main.frag
  DisabledEffects disable;           // --disable
  std::string preset;                // a quality preset name, checked; empty: the scene's
  std::vector<std::pair<std::string, std::string>> defines;  // -D, parsed
  std::vector<std::filesystem::path> allow_include;          // canonical directories
  SceneOverrides set;                // --set, in order
  std::vector<UniformValue> uniforms;  // --uniform
  std::vector<std::string> aov_channels;  // render/aov.h's channels; empty: no AOVs
  Specialization specialize = Specialization::folded;
  bool strict = false;
  double timeout = 0.0;              // seconds for this image (each frame of a sequence); 0: none
  int tile_size = kTileSize;         // largest square per draw (render/tiles.h)
  int tile_still = 0;                // forced tiled-still side (tests); 0: past the limits only
  ShadertoyOptions shadertoy;
  Dispatch dispatch = Dispatch::fragment;  // automatic: pipeline/dispatch_probe.h chooses
  std::optional<ComputeGroup> compute_group;  // none: 8x8, or auto's measured group
  GraphEval graph_eval = GraphEval::auto_;   // a graph scene's map(): --graph-eval
  bool prune = true;                         // --no-prune: the whole graph everywhere
  float cell_size = 0.0f;                    // the pruning grid's cells; 0: from the node count
  bool verbose = false;

  bool aovs() const { return !aov_channels.empty(); }
  // The assembler's options this job asks for (defines, includes,
  // specialization, uniforms); AOV outputs added when it has AOVs.
  AssembleOptions assemble_options() const;
};

// An animation as an image sequence (pipeline/sequence.h): `frame` gives
// everything but the time, which is frame / fps for each frame.
struct SequenceJob {
  FrameJob frame;          // frame.output, time and frame unused; frame.fps: none gives kSceneFps, or a shader's own
  FrameRange range;        // both ends included
  Shard shard;             // this process's part: 1/1 is all
  ShardMode mode = ShardMode::stride;
  FramePattern pattern{"frame_%04d.png"};  // where frame f is written
  std::filesystem::path video;   // encoded afterwards when given
  std::filesystem::path ffmpeg;  // found on PATH, when video is given
  bool no_write = false;   // render but discard (throughput measurements)
  bool force = false;      // render every frame again (pipeline/sequence_state.h)
};

}  // namespace ms
