#include "render/graph.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>

#include <glm/vec2.hpp>

#include "core/clock.h"
#include "core/error.h"
#include "render/audio_texture.h"
#include "render/cubemap.h"
#include "render/graph_state.h"
#include "render/tiles.h"
#include "render/video_texture.h"
#include "render/uniforms.h"
#include "shader/assemble.h"

namespace ms {
namespace {

GLint min_filter(TexFilter f) {
  return f == TexFilter::nearest ? GL_NEAREST : f == TexFilter::linear ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
}

// Past the GL's limit the upload fails with a bare GL_INVALID_VALUE: say
// which file and what the limit is instead.
void check_texture_size(const GraphInput& in) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  const Image& img = *in.image;
  if (max <= 0 || (img.width <= max && img.height <= max)) return;
  fail_input("the texture is " + std::to_string(img.width) + "x" + std::to_string(img.height) +
                 ", larger than this GL's GL_MAX_TEXTURE_SIZE of " + std::to_string(max),
             in.file, 0, {}, "scale it to at most " + std::to_string(max) + " pixels a side");
}

// An image as a texture: rows bottom first when vflip (Shadertoy's upright
// picture, uv (0,0) at its lower left), as stored otherwise.
GLuint upload(const GraphInput& in) {
  check_texture_size(in);
  const Image& img = *in.image;
  const int w = img.width, h = img.height, nc = img.nchannels();
  const bool mips = in.sampler.filter == TexFilter::mipmap;
  GLenum internal = in.single_channel ? GL_R8 : in.sampler.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
  if (!in.eight_bit) internal = in.single_channel ? GL_R32F : GL_RGBA32F;
  std::vector<float> rgba(static_cast<size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    const int src_y = in.sampler.vflip ? h - 1 - y : y;
    for (int x = 0; x < w; ++x) {
      const float* s = img.pixels.data() + (static_cast<size_t>(src_y) * w + x) * nc;
      float* d = rgba.data() + (static_cast<size_t>(y) * w + x) * 4;
      d[0] = s[0];
      d[1] = nc > 2 ? s[1] : s[0];
      d[2] = nc > 2 ? s[2] : s[0];
      d[3] = nc == 4 ? s[3] : nc == 2 ? s[1] : 1.0f;
    }
  }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, mips ? mip_levels(w, h) : 1, internal, w, h);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
  if (mips) glGenerateMipmap(GL_TEXTURE_2D);
  return tex;
}

// A volume as a GL_TEXTURE_3D, 8-bit as Shadertoy stores its volumes.
GLuint upload(const Volume& v, const Sampler& sampler) {
  const bool mips = sampler.filter == TexFilter::mipmap;
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_3D, tex);
  glTexStorage3D(GL_TEXTURE_3D, mips ? mip_levels(v.size, v.size) : 1, v.channels == 1 ? GL_R8 : GL_RGBA8, v.size,
                 v.size, v.size);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, v.size, v.size, v.size, v.channels == 1 ? GL_RED : GL_RGBA,
                  GL_UNSIGNED_BYTE, v.voxels.data());
  if (mips) glGenerateMipmap(GL_TEXTURE_3D);
  return tex;
}

// Where a channel's texture binds: its sampler type's target.
GLenum gl_target(ChannelType t) {
  return t == ChannelType::cube ? GL_TEXTURE_CUBE_MAP : t == ChannelType::tex3d ? GL_TEXTURE_3D : GL_TEXTURE_2D;
}

}  // namespace

PassGraph::PassGraph(std::vector<PassSource> passes, ProgramCache* cache)
    : passes_(std::move(passes)), gpu_(std::make_unique<Gpu>()) {
  if (passes_.empty() || passes_.back().output != -1) fail_system("internal: a pass graph must end in the frame's pass");
  bool reads_cube_a = false;
  for (const PassSource& p : passes_) {
    programs_.push_back(cache ? cache->get(fullscreen_vertex_source(), p.source)
                              : std::make_shared<const Program>(fullscreen_vertex_source(), p.source));
    if (p.output >= 0 && p.output < 4) gpu_->used[p.output] = gpu_->written[p.output] = true;
    // A buffer or Cube A that no pass writes is still made, and stays 0 (as on Shadertoy).
    for (const GraphInput& in : p.inputs) {
      if (in.kind == InputKind::buffer && in.buffer >= 0 && in.buffer < 4) gpu_->used[in.buffer] = true;
      reads_cube_a = reads_cube_a || (in.kind == InputKind::cubemap && !in.cube);
    }
  }
  Gpu& g = *gpu_;
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // as WebGL2 filters cube maps
  if (has_cube_pass() || reads_cube_a) {
    int levels = 1;  // a chain when some pass samples Cube A mipmapped
    for (const PassSource& p : passes_)
      for (const GraphInput& in : p.inputs)
        if (in.kind == InputKind::cubemap && !in.cube && in.sampler.filter == TexFilter::mipmap) levels = 2;
    g.cube_a = std::make_unique<CubeBuffer>(levels);
  }
  glGenVertexArrays(1, &g.vao);
  const float black[4] = {0, 0, 0, 1};
  glGenTextures(1, &g.black);
  glBindTexture(GL_TEXTURE_2D, g.black);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, black);
  glGenTextures(1, &g.keyboard);
  glBindTexture(GL_TEXTURE_2D, g.keyboard);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_R8, 256, 3);
  const KeyboardState none{};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 256, 3, GL_RED, GL_UNSIGNED_BYTE, none.data());
  for (int f = 0; f < 3; ++f)
    for (int w = 0; w < 3; ++w) {
      GLuint s = 0;
      glGenSamplers(1, &s);
      glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, min_filter(static_cast<TexFilter>(f)));
      glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, f == 0 ? GL_NEAREST : GL_LINEAR);
      const GLint wrap = w == 0 ? GL_CLAMP_TO_EDGE : w == 1 ? GL_REPEAT : GL_MIRRORED_REPEAT;
      glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
      glSamplerParameteri(s, GL_TEXTURE_WRAP_R, wrap);  // volumes (and cubemaps' third coordinate)
      g.samplers[f * 3 + w] = s;
    }
  for (const PassSource& p : passes_)
    for (const GraphInput& in : p.inputs)
      if (in.kind == InputKind::texture && in.image && !g.textures.count(upload_key(in)))
        g.textures[upload_key(in)] = upload(in);
      else if (in.kind == InputKind::cubemap && in.cube && !g.cubes.count(upload_key(in)))
        g.cubes[upload_key(in)] = upload_cube(*in.cube, in.sampler);
      else if (in.kind == InputKind::volume && in.volume && !g.volumes.count(upload_key(in)))
        g.volumes[upload_key(in)] = upload(*in.volume, in.sampler);
      else if (in.audio && !g.audio.count(in.audio.get())) {
        GLuint tex = 0;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_R8, kAudioTexWidth, 2);
        g.audio[in.audio.get()] = tex;
      } else if (in.video) {
        g.videos.add(in.video, in.sampler);
      }
  pass_ms_.assign(passes_.size(), 0.0);
}

PassGraph::~PassGraph() {
  Gpu& g = *gpu_;
  for (Buffer& b : g.buffers) {
    glDeleteFramebuffers(2, b.fbo);
    glDeleteTextures(2, b.tex);
  }
  for (auto& [key, tex] : g.textures) glDeleteTextures(1, &tex);
  for (auto& [key, tex] : g.volumes) glDeleteTextures(1, &tex);
  for (auto& [key, tex] : g.cubes) glDeleteTextures(1, &tex);
  for (auto& [clip, tex] : g.audio) glDeleteTextures(1, &tex);
  for (auto& [key, s] : g.samplers) glDeleteSamplers(1, &s);
  glDeleteTextures(1, &g.black);
  glDeleteTextures(1, &g.keyboard);
  glDeleteVertexArrays(1, &g.vao);
}

std::vector<int> PassGraph::buffers() const {
  std::vector<int> out;
  for (int b = 0; b < 4; ++b)
    if (gpu_->written[b]) out.push_back(b);
  if (has_cube_pass()) out.push_back(kCubeA);
  return out;
}

bool PassGraph::has_cube_pass() const {
  return std::any_of(passes_.begin(), passes_.end(), [](const PassSource& p) { return p.output == kCubeA; });
}

void PassGraph::bind_inputs(size_t pass, int w, int h, float res[4][3]) {
  Gpu& g = *gpu_;
  for (int c = 0; c < 4; ++c) {
    const GraphInput& in = passes_[pass].inputs[c];
    GLuint tex = g.black;
    float rw = 0, rh = 0, rd = 1;
    switch (in.kind) {
      case InputKind::buffer:
        tex = g.buffers[in.buffer].tex[g.buffers[in.buffer].latest];  // as it stands now
        rw = static_cast<float>(w);
        rh = static_cast<float>(h);
        break;
      case InputKind::texture:
        tex = g.textures.at(upload_key(in));
        rw = static_cast<float>(in.image->width);
        rh = static_cast<float>(in.image->height);
        break;
      case InputKind::keyboard:
        tex = g.keyboard;
        rw = 256;
        rh = 3;
        break;
      case InputKind::cubemap:
        tex = in.cube ? g.cubes.at(upload_key(in)) : g.cube_a->texture();  // Cube A as it stands now
        rw = rh = static_cast<float>(in.cube ? in.cube->size : g.cube_a->size());
        break;
      case InputKind::volume:
        tex = g.volumes.at(upload_key(in));
        rw = rh = rd = static_cast<float>(in.volume->size);
        break;
      case InputKind::music:
      case InputKind::musicstream:
        if (!in.audio) break;  // missing (--missing-media): not loaded, so nothing bound, as on Shadertoy
        tex = g.audio.at(in.audio.get());
        rw = kAudioTexWidth;
        rh = 2;
        break;
      case InputKind::video:
        tex = g.videos.texture(in.video.get());
        rw = static_cast<float>(in.video->info().width);
        rh = static_cast<float>(in.video->info().height);
        break;
      default:
        break;
    }
    glActiveTexture(GL_TEXTURE0 + c);
    glBindTexture(gl_target(channel_type(in.kind)), tex);
    int filter = in.kind == InputKind::keyboard ? 0 : static_cast<int>(in.sampler.filter);
    const bool audio = in.kind == InputKind::music || in.kind == InputKind::musicstream;
    if (audio && in.sampler.filter == TexFilter::mipmap) filter = 1;  // no mip chain: Shadertoy offers none for audio
    const int wrap = in.kind == InputKind::keyboard ? 0 : static_cast<int>(in.sampler.wrap);
    glBindSampler(c, in.kind == InputKind::none ? 0 : g.samplers.at(filter * 3 + wrap));
    res[c][0] = rw;
    res[c][1] = rh;
    res[c][2] = in.kind == InputKind::none || (audio && !in.audio) ? 0.0f : rd;
  }
  glActiveTexture(GL_TEXTURE0);
}

namespace {

ShadertoyInputs shadertoy_inputs(const FrameInputs& in, float res[4][3], const std::array<GraphInput, 4>& inputs) {
  ShadertoyInputs st;
  st.time = in.time;
  st.time_delta = in.time_delta;
  st.frame = in.frame;
  std::copy(std::begin(in.mouse), std::end(in.mouse), st.mouse);
  std::memcpy(st.channel_resolution, res, sizeof st.channel_resolution);
  for (int c = 0; c < 4; ++c) {
    // Audio that never loaded never plays: its iChannelTime stays 0.
    const GraphInput& g = inputs[c];
    const bool unloaded = (g.kind == InputKind::music || g.kind == InputKind::musicstream) && !g.audio;
    st.channel_time[c] = unloaded ? 0.0f : in.time;
  }
  return st;
}

// Wall milliseconds once the GL has finished what it was given: a pass
// timed between two of these is that pass alone, on any driver.
double finished_ms() {
  glFinish();
  return clock_seconds() * 1e3;
}

void unbind_samplers() {
  for (int c = 0; c < 4; ++c) glBindSampler(c, 0);
}

}  // namespace

void PassGraph::draw_buffer_pass(size_t pass, const FrameInputs& in, const FrameParams& p) {
  Gpu& g = *gpu_;
  Buffer& buf = g.buffers[passes_[pass].output];
  const int target = 1 - buf.latest;
  glBindFramebuffer(GL_FRAMEBUFFER, buf.fbo[target]);
  glViewport(0, 0, p.width, p.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(g.vao);
  const Program& prog = *programs_[pass];
  glUseProgram(prog.id());
  float res[4][3];
  bind_inputs(pass, p.width, p.height, res);
  const ShadertoyInputs st = shadertoy_inputs(in, res, passes_[pass].inputs);
  set_shadertoy_uniforms(prog, p.width, p.height, st);
  if (passes_[pass].uniforms == PassUniforms::glslviewer)
    set_glslviewer_uniforms(prog, p.width, p.height, st, passes_[pass].inputs);
  if (in.extra) (*in.extra)(prog);
  prog.set("uJitter", glm::vec2(0.5f));
  // Tile by tile, as FrameRenderer draws: a bounded draw, a deadline check.
  glEnable(GL_SCISSOR_TEST);
  for (const Tile& t : split_tiles(p.width, p.height, p.tile_size)) {
    glScissor(t.x, t.y, t.width, t.height);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (p.deadline) {
      glFinish();
      if (p.deadline->expired()) {
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        p.deadline->check("the render");
      }
    } else {
      glFlush();
    }
  }
  glDisable(GL_SCISSOR_TEST);
  unbind_samplers();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (buf.levels > 1) {
    glBindTexture(GL_TEXTURE_2D, buf.tex[target]);
    glGenerateMipmap(GL_TEXTURE_2D);
  }
  buf.latest = target;  // later passes, and the next frame, read this
}

void PassGraph::draw_cube_pass(size_t pass, const FrameInputs& in, const FrameParams& p) {
  const Program& prog = *programs_[pass];
  const int n = gpu_->cube_a->size();
  gpu_->cube_a->draw(prog.id(), gpu_->vao, [&](int face) {
    float res[4][3];
    bind_inputs(pass, p.width, p.height, res);
    // iResolution: the face, as Shadertoy
    set_shadertoy_uniforms(prog, n, n, shadertoy_inputs(in, res, passes_[pass].inputs));
    prog.set("uCubeFace", face);
    if (in.extra) (*in.extra)(prog);
  }, p.deadline);
  unbind_samplers();
}

void PassGraph::update_timed_inputs(const FrameInputs& in, const FrameParams& p) {
  gpu_->videos.update(in.time, p.deadline);
  for (auto& [clip, tex] : gpu_->audio) {
    const AudioTexels t = audio_texels(*clip, in.time, in.time_delta);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kAudioTexWidth, 2, GL_RED, GL_UNSIGNED_BYTE, t.data());
  }
}

void PassGraph::step_buffers(const FrameInputs& in, const FrameParams& p) {
  ensure_buffers(p.width, p.height);
  update_timed_inputs(in, p);
  Gpu& g = *gpu_;
  if (in.keyboard) {
    glBindTexture(GL_TEXTURE_2D, g.keyboard);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 256, 3, GL_RED, GL_UNSIGNED_BYTE, in.keyboard->data());
  }
  for (size_t i = 0; i + 1 < passes_.size(); ++i) {
    const double t0 = timing_ ? finished_ms() : 0.0;
    if (passes_[i].output == kCubeA) draw_cube_pass(i, in, p);
    else draw_buffer_pass(i, in, p);
    if (timing_) pass_ms_[i] = finished_ms() - t0;
  }
}

void PassGraph::draw(FrameRenderer& renderer, const Program& post, const FrameInputs& in, const FrameParams& p,
                     bool step) {
  draw([&](const Program& prog, const UniformFn& set_uniforms) { renderer.draw(prog, set_uniforms, post, p); }, in, p,
       step);
}

void PassGraph::draw(const DrawLast& draw_last, const FrameInputs& in, const FrameParams& p, bool step) {
  if (step) step_buffers(in, p);
  else {
    ensure_buffers(p.width, p.height);
    update_timed_inputs(in, p);
  }
  const size_t last = passes_.size() - 1;
  const PassSource& frame_pass = passes_[last];
  const double t0 = timing_ ? finished_ms() : 0.0;
  draw_last(*programs_[last], [&](const Program& prog) {
    float res[4][3];
    bind_inputs(last, p.width, p.height, res);
    const ShadertoyInputs st = shadertoy_inputs(in, res, frame_pass.inputs);
    if (frame_pass.uniforms == PassUniforms::shadertoy) {
      set_shadertoy_uniforms(prog, p.resolution_width(), p.resolution_height(), st);
    } else if (frame_pass.uniforms == PassUniforms::glslviewer) {
      set_shadertoy_uniforms(prog, p.resolution_width(), p.resolution_height(), st);
      set_glslviewer_uniforms(prog, p.resolution_width(), p.resolution_height(), st, frame_pass.inputs);
    } else {
      if (!in.scene) fail_system("internal: a scene pass without its scene");
      set_scene_uniforms(prog, *in.scene, p.resolution_width(), p.resolution_height(), in.time, in.frame);
    }
    if (in.extra) (*in.extra)(prog);
  });
  unbind_samplers();
  if (timing_) pass_ms_[last] = finished_ms() - t0;
}

std::vector<std::string> PassGraph::unbound_sampled() const {
  std::vector<std::string> out;
  for (size_t i = 0; i < passes_.size(); ++i)
    for (int c = 0; c < 4; ++c)
      if (const GraphInput& in = passes_[i].inputs[c];
          in.kind == InputKind::none && programs_[i]->loc(in.uniform.empty() ? "iChannel" + std::to_string(c) : in.uniform) >= 0)
        out.push_back(passes_[i].name + " " + (in.uniform.empty() ? "iChannel" + std::to_string(c) : in.uniform));
  return out;
}

}  // namespace ms
