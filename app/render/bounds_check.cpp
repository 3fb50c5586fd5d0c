#include "render/bounds_check.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/format.h"
#include "gl/gl.h"

namespace ms {
namespace {

constexpr int kProbeN = 64;  // sdf_shaders/bounds_probe.glsl's kBoundsProbeN

std::string num(float v) { return printf_number("%.3g", v); }

// The caller's GL state (the viewer draws on afterwards).
struct SavedState {
  GLint fbo = 0, program = 0, vao = 0, viewport[4] = {0, 0, 0, 0};
  SavedState() {
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
    glGetIntegerv(GL_VIEWPORT, viewport);
  }
  ~SavedState() {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glUseProgram(program);
    glBindVertexArray(vao);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  }
};

}  // namespace

BoundsCheck check_bounds(const Scene& scene, AssembleOptions opts, const UniformFn& set_uniforms,
                         ProgramCache* cache) {
  BoundsCheck c;
  if (scene.bounds.kind == BoundsKind::none || !scene.quality.bounds || !scene.shadertoy_file.empty()) return c;
  // The probe replaces main.frag's image: the frame's own outputs and views do not apply.
  std::erase_if(opts.defines, [](const auto& d) {
    return d.first == "AOV_OUTPUTS" || d.first == "DEBUG_VIEW" || d.first == "FUSED_POST";
  });
  opts.defines.emplace_back("BOUNDS_PROBE", "1");
  const ShaderSource src = assemble_scene(scene, opts);
  std::shared_ptr<const Program> owned;
  const Program* prog = nullptr;
  if (cache) {
    owned = cache->get(fullscreen_vertex_source(), src);
  } else {
    owned = std::make_shared<const Program>(fullscreen_vertex_source(), src);
  }
  prog = owned.get();

  const SavedState saved;
  const int w = kProbeN, h = 6 * kProbeN;
  GLuint tex = 0, fbo = 0, vao = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glViewport(0, 0, w, h);
  glUseProgram(prog->id());
  if (set_uniforms) set_uniforms(*prog);
  glDisable(GL_BLEND);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> px(static_cast<size_t>(w) * h * 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, px.data());
  glDeleteVertexArrays(1, &vao);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &tex);

  for (size_t i = 0; i < px.size(); i += 4) {
    const float d = px[i + 3];
    ++c.samples;
    if (!(d < 0.0f)) continue;  // NaN is the NaN guard's business, not this one's
    ++c.negative;
    if (d < c.min_value) {
      c.min_value = d;
      c.worst = {px[i], px[i + 1], px[i + 2]};
    }
  }
  return c;
}

std::string bounds_warning(const std::string& scene_file, const BoundsCheck& c) {
  if (c.ok()) return {};
  return scene_file + ": warning: map() is negative on the [bounds] surface at " + std::to_string(c.negative) +
         " of " + std::to_string(c.samples) + " points (down to " + num(c.min_value) + " at (" + num(c.worst.x) +
         ", " + num(c.worst.y) + ", " + num(c.worst.z) + ")): what crosses it is cut off; grow [bounds]";
}

}  // namespace ms
