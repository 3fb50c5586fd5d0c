// A frame as an ordered list of passes: each pass is a program with up to
// four inputs and one output. A Shadertoy project's buffer passes A..D draw
// into RGBA32F buffers, in order, then its Image pass draws the frame through
// FrameRenderer (samples, tiles, the post pass); an SDF scene is a graph of
// one pass.
//
// Each buffer holds two textures, and a pass reads a buffer as it stands
// when the pass runs: a pass reading its own buffer, or one later in the
// order, sees the previous frame's contents; one reading an earlier
// buffer sees this frame's. Buffers are cleared to 0 before frame 0 and
// made once per size: nothing is reallocated or read back per frame. A
// buffer (or Cube A) some pass reads and none writes is made too, and
// stays 0, as on Shadertoy.
//
//   std::vector<PassSource> specs = ...;       // pipeline/input.h: no GL yet
//   PassGraph g(specs);                        // compiles, uploads textures
//   g.draw(renderer, post, frame, params);     // buffers, then the frame
//   g.reset();                                 // the next draw is frame 0
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "io/audio.h"
#include "io/cube_faces.h"
#include "io/image.h"
#include "io/video_input.h"
#include "render/frame.h"
#include "render/program.h"
#include "render/program_cache.h"
#include "scene/project.h"
#include "scene/scene.h"
#include "preprocess/preprocess.h"

namespace ms {

// A cube of 8-bit voxels, `size` on each side: a volume input's contents.
struct Volume {
  int size = 0;
  int channels = 1;                   // 1 (sampled (v, 0, 0, 1)) or 4
  std::vector<std::uint8_t> voxels;   // channels per voxel; x fastest, then y, then z
};

// One channel as the GL binds it; made before any context exists.
struct GraphInput {
  InputKind kind = InputKind::none;  // none, buffer, texture, keyboard, cubemap, volume, music, video here
  int buffer = -1;                    // buffer: 0..3 (A..D)
  std::shared_ptr<const Image> image; // texture: decoded (top row first)
  std::string file;                   // texture: the file it was read from, for errors; empty: made here
  std::shared_ptr<const Volume> volume;  // volume: its voxels
  std::shared_ptr<const CubeFaces> cube; // cubemap: its six faces (null: the Cube A pass, buffer kCubeA)
  std::shared_ptr<const AudioClip> audio;  // music, musicstream: the decoded clip (render/audio_texture.h per frame)
  std::shared_ptr<VideoStream> video;      // video: its decoder (render/video_texture.h per frame)
  bool eight_bit = true;              // texture: stored as RGBA8 (PNG, JPEG), else as float (EXR, HDR)
  bool single_channel = false;        // texture: uploaded as one channel, sampled (v, 0, 0, 1)
  Sampler sampler;
  std::string uniform;                // glslViewer: the sampler's name (u_tex0); empty: iChannelN
};

enum class PassUniforms { scene, shadertoy, glslviewer };  // glslviewer: Shadertoy's plus u_* (render/uniforms.h)

struct PassSource {
  std::string name;     // "Buffer A", "Image", or the scene's name
  ShaderSource source;  // the assembled fragment shader
  PassUniforms uniforms = PassUniforms::scene;
  std::array<GraphInput, 4> inputs{};
  int output = -1;      // the buffer it writes, 0..3, or kCubeA (render/cubemap.h); -1: the frame (the last pass)
};

// Shadertoy's keyboard texture, 256x3: row 0 down, row 1 pressed this
// frame, row 2 toggled, by key code (0 or 255). All zero headless.
using KeyboardState = std::array<std::uint8_t, 256 * 3>;

// What changes from frame to frame.
struct FrameInputs {
  const Scene* scene = nullptr;  // a scene pass's uniforms, posed at `time`
  float time = 0.0f;             // uTime / iTime, seconds
  float time_delta = 1.0f / 60.0f;
  int frame = 0;                 // uFrame / iFrame
  float mouse[4] = {0, 0, 0, 0};  // iMouse
  const KeyboardState* keyboard = nullptr;  // null: all keys up
  // More uniforms of every pass, after the standard ones (the viewer's sliders).
  const std::function<void(const Program&)>* extra = nullptr;
};

class PassGraph {
 public:
  // Needs the GL context current. Programs come from `cache` when given
  // (the viewer), else are compiled here; a compile error throws as
  // Program does, naming the pass's file:line.
  explicit PassGraph(std::vector<PassSource> passes, ProgramCache* cache = nullptr);
  ~PassGraph();
  PassGraph(const PassGraph&) = delete;
  PassGraph& operator=(const PassGraph&) = delete;

  // One frame: each buffer pass into its buffer (one sample at pixel
  // centres, tile by tile as FrameRenderer draws, deadline included), then
  // the last pass through `renderer` with p's samples and post pass.
  // `step` false: the buffers stay as they are (the viewer paused) and only
  // the last pass draws.
  void draw(FrameRenderer& renderer, const Program& post, const FrameInputs& in, const FrameParams& p,
            bool step = true);
  // The same frame with the last pass drawn by `draw_last`, given that
  // pass's program and its uniforms (its inputs bound on units 0..3 when
  // they run): the compute dispatch draws the scene pass this way
  // (render/compute_frame.h) with a program of its own.
  using DrawLast = std::function<void(const Program& last, const UniformFn& set_uniforms)>;
  void draw(const DrawLast& draw_last, const FrameInputs& in, const FrameParams& p, bool step = true);
  // The buffer passes alone: a frame whose image nobody looks at (the
  // frames a still replays before its own).
  void step_buffers(const FrameInputs& in, const FrameParams& p);
  // Every buffer to 0: the next draw is frame 0 again.
  void reset();
  // The buffers of `old` that this graph has too, copied on the GPU as
  // they stand: a reload of one pass keeps the others' state evolving.
  void adopt_buffers(const PassGraph& old);

  size_t size() const { return passes_.size(); }
  const std::string& name(size_t pass) const { return passes_[pass].name; }
  const Program& program(size_t pass) const { return *programs_[pass]; }
  const PassSource& pass(size_t pass) const { return passes_[pass]; }
  bool stateful() const { return passes_.size() > 1; }
  // The buffers some pass writes (0..3), ascending, then kCubeA for a Cube A pass.
  std::vector<int> buffers() const;
  bool has_cube_pass() const;
  // A buffer's contents as they stand (RGBA float, GL's row order), and
  // back: the checkpoints of a sequence (bit for bit). kCubeA: the six
  // faces stacked (render/cubemap.h).
  Image read_buffer(int buffer) const;
  void write_buffer(int buffer, const Image& img);
  // "Image iChannel2": channels a program samples with nothing bound (they
  // read (0, 0, 0, 1), as an unbound Shadertoy channel does).
  std::vector<std::string> unbound_sampled() const;
  // Each pass's wall time in the last draw, ms, when timed: a glFinish
  // before and after each pass (bench; slower, so off by default).
  void set_timing(bool on) { timing_ = on; }
  const std::vector<double>& pass_ms() const { return pass_ms_; }

 private:
  struct Buffer;
  struct Gpu;
  void ensure_buffers(int w, int h);
  void clear_buffers();  // the 2D buffers to 0 (reset() clears Cube A too)
  void bind_inputs(size_t pass, int w, int h, float channel_res[4][3]);
  void draw_buffer_pass(size_t pass, const FrameInputs& in, const FrameParams& p);
  void draw_cube_pass(size_t pass, const FrameInputs& in, const FrameParams& p);  // Cube A's six faces
  void update_timed_inputs(const FrameInputs& in, const FrameParams& p);  // inputs that follow iTime (audio, video), once per frame

  std::vector<PassSource> passes_;
  std::vector<std::shared_ptr<const Program>> programs_;
  std::unique_ptr<Gpu> gpu_;
  bool timing_ = false;
  std::vector<double> pass_ms_;
};

}  // namespace ms
