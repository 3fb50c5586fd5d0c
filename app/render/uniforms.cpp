#include "render/uniforms.h"

#include <array>
#include <cmath>
#include <iterator>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/audio_texture.h"
#include "scene/camera_frame.h"
#include "shader/specialize.h"

namespace ms {
namespace {

float radians(float deg) { return deg * 3.14159265358979f / 180.0f; }

// Each material value by its field of uMaterials[i] and by its key, which
// names the uniform the viewer keeps it live in (uLive_materials_i_KEY,
// shader/specialize.h live_uniform_name).
struct MaterialValue {
  const char* field;
  const char* key;
  glm::vec3 Material::*vec = nullptr;
  float Material::*scalar = nullptr;
};
const MaterialValue kMaterialValues[] = {
    {"color", "color", &Material::color},
    {"ka", "ambient", nullptr, &Material::ambient},
    {"kd", "diffuse", nullptr, &Material::diffuse},
    {"ks", "specular", nullptr, &Material::specular},
    {"shininess", "shininess", nullptr, &Material::shininess},
    {"reflectivity", "reflectivity", nullptr, &Material::reflectivity},
    {"color2", "color2", &Material::color2},
    {"patternScale", "pattern_scale", nullptr, &Material::pattern_scale},
    {"patternVelocity", "pattern_velocity", &Material::pattern_velocity},
};

// The uniform names of each light and material slot, built once: every
// frame sets them all, and building the strings anew took about a third
// of stilllife's submit time (docs/gpu-bench.md#per-frame-host-costs). Static
// locals: a compile worker's thread sets uniforms too, and their
// initialization is thread-safe.
struct LightNames {
  std::string pos, color, size, atten, live_pos, live_color, live_size, live_atten;
};
const std::array<LightNames, kMaxLights>& light_names() {
  static const std::array<LightNames, kMaxLights> names = [] {
    std::array<LightNames, kMaxLights> t;
    for (size_t i = 0; i < kMaxLights; ++i) {
      const std::string b = "uLights[" + std::to_string(i) + "].", l = "uLive_lights_" + std::to_string(i) + "_";
      t[i] = {b + "pos", b + "color", b + "size", b + "atten", l + "pos", l + "color", l + "size", l + "atten"};
    }
    return t;
  }();
  return names;
}

constexpr size_t kMaterialValueCount = std::size(kMaterialValues);
struct MaterialNames {
  std::string pattern;
  std::array<std::string, kMaterialValueCount> field, live;  // by kMaterialValues' order
};
const std::array<MaterialNames, kMaxMaterials>& material_names() {
  static const std::array<MaterialNames, kMaxMaterials> names = [] {
    std::array<MaterialNames, kMaxMaterials> t;
    for (size_t i = 0; i < kMaxMaterials; ++i) {
      const std::string b = "uMaterials[" + std::to_string(i) + "].", l = "uLive_materials_" + std::to_string(i) + "_";
      t[i].pattern = b + "pattern";
      for (size_t k = 0; k < kMaterialValueCount; ++k) {
        t[i].field[k] = b + kMaterialValues[k].field;
        t[i].live[k] = l + kMaterialValues[k].key;
      }
    }
    return t;
  }();
  return names;
}

// Shadertoy's per-channel names, iChannelN, iChannelTime[N], iChannelResolution[N].
struct ChannelNames {
  std::string sampler, time, resolution;
};
const std::array<ChannelNames, 4>& channel_names() {
  static const std::array<ChannelNames, 4> names = [] {
    std::array<ChannelNames, 4> t;
    for (int i = 0; i < 4; ++i) {
      const std::string n = std::to_string(i);
      t[i] = {"iChannel" + n, "iChannelTime[" + n + "]", "iChannelResolution[" + n + "]"};
    }
    return t;
  }();
  return names;
}

}  // namespace

void set_scene_uniforms(const Program& p, const Scene& s, int width, int height, float time, int frame) {
  p.set("uResolution", glm::vec2(width, height));
  p.set("uTime", time);
  p.set("uFrame", frame);
  p.set("uCamPos", s.camera.position);
  p.set("uCamTarget", s.camera.target);
  p.set("uCamUp", s.camera.up);
  p.set("uFovY", radians(s.camera.fov_deg));
  // The frame every primary ray is built from, once here instead of per pixel.
  const CameraFrame cf = camera_frame(s.camera);
  const glm::mat3 basis(cf.right, cf.up, cf.forward);
  p.set("uCamBasis", basis);
  p.set("uCamTanHalfFov", cf.tan_half_fov);
  p.set("uSkyHorizon", s.sky.horizon);
  p.set("uSkyZenith", s.sky.zenith);
  p.set("uAmbient", s.sky.ambient);
  // BOUNDS_UNIFORMS (sdf_shaders/bounds.glsl): BOUNDS_A and BOUNDS_B as assemble.cpp folds them.
  if (s.bounds.kind == BoundsKind::box) {
    p.set("uBoundsA", glm::vec4(s.bounds.min, 0.0f));
    p.set("uBoundsB", glm::vec4(s.bounds.max, 0.0f));
  } else if (s.bounds.kind == BoundsKind::sphere) {
    p.set("uBoundsA", glm::vec4(s.bounds.center, s.bounds.radius));
  }
  if (!s.sky.environment.empty()) {  // ENV_MAP (render/environment.h): the map turned by -rotation into world
    const float a = radians(s.sky.rotation);
    const glm::mat3 rot(std::cos(a), 0.0f, std::sin(a), 0.0f, 1.0f, 0.0f, -std::sin(a), 0.0f, std::cos(a));
    p.set("uEnvRotation", rot);
    p.set("uEnvIntensity", s.sky.intensity);
    std::array<glm::vec3, 9> sh = s.sky.irradiance;
    for (glm::vec3& c : sh) c *= s.sky.intensity;
    p.set("uEnvSH[0]", sh.data(), static_cast<int>(sh.size()));
  }

  // A specialized shader may have folded some of these into constants (the
  // same values: glsl_light); Program::set skips their -1 locations.
  for (size_t i = 0; i < s.lights.size(); ++i) {
    const GlslLight l = glsl_light(s.lights[i]);
    const LightNames& n = light_names().at(i);  // load.cpp refuses more than kMaxLights
    p.set(n.pos, l.pos);
    p.set(n.color, l.color);
    p.set(n.size, l.size);
    p.set(n.atten, l.atten);
    // A value the viewer keeps live in a folded table (shader/specialize.h live_uniform_name).
    p.set(n.live_pos, glm::vec3(l.pos));
    p.set(n.live_color, l.color);
    p.set(n.live_size, l.size);
    p.set(n.live_atten, l.atten);
  }
  for (size_t i = 0; i < s.materials.size(); ++i) {
    const Material& m = s.materials[i];
    const MaterialNames& n = material_names().at(i);
    p.set(n.pattern, m.pattern == Pattern::checker ? 1 : 0);
    for (size_t k = 0; k < std::size(kMaterialValues); ++k) {
      const MaterialValue& v = kMaterialValues[k];
      if (v.vec) {
        p.set(n.field[k], m.*v.vec);
        p.set(n.live[k], m.*v.vec);
      } else {
        p.set(n.field[k], m.*v.scalar);
        p.set(n.live[k], m.*v.scalar);
      }
    }
  }
}

BlackChannels::BlackChannels() {
  const float black[4] = {0, 0, 0, 1};
  glGenTextures(1, &tex_);
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, black);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

BlackChannels::~BlackChannels() { glDeleteTextures(1, &tex_); }

void BlackChannels::bind() const {
  for (int i = 0; i < 4; ++i) {
    glActiveTexture(GL_TEXTURE0 + i);
    glBindTexture(GL_TEXTURE_2D, tex_);
  }
  glActiveTexture(GL_TEXTURE0);
}

void set_shadertoy_uniforms(const Program& p, int width, int height, const ShadertoyInputs& in) {
  p.set("iResolution", glm::vec3(width, height, 1.0f));
  p.set("iTime", in.time);
  p.set("iTimeDelta", in.time_delta);
  p.set("iFrameRate", in.time_delta > 0 ? 1.0f / in.time_delta : 0.0f);
  p.set("iFrame", in.frame);
  p.set("iMouse", glm::make_vec4(in.mouse));
  p.set("iDate", glm::vec4(2000.0f, 0.0f, 1.0f, in.time));
  p.set("iSampleRate", kShadertoySampleRate);  // Shadertoy's constant, whatever audio is bound
  for (int i = 0; i < 4; ++i) {
    const ChannelNames& n = channel_names()[i];
    p.set(n.sampler, i);
    p.set(n.time, in.channel_time[i]);
    p.set(n.resolution, glm::make_vec3(in.channel_resolution[i]));
  }
}

}  // namespace ms

namespace ms {

void set_glslviewer_uniforms(const Program& p, int width, int height, const ShadertoyInputs& in,
                             const std::array<GraphInput, 4>& inputs) {
  p.set("u_resolution", glm::vec2(width, height));
  p.set("u_time", in.time);
  p.set("u_delta", in.time_delta);
  p.set("u_frame", in.frame);
  p.set("u_mouse", glm::vec2(in.mouse[0], in.mouse[1]));
  p.set("u_date", glm::vec4(2000.0f, 0.0f, 1.0f, in.time));  // as iDate: never the wall clock
  // A 2D canvas: glslViewer sets these to identity (u_model to (1, 1, 1)).
  for (const char* m : {"u_modelMatrix", "u_viewMatrix", "u_projectionMatrix", "u_modelViewProjectionMatrix"})
    p.set(m, glm::mat4(1.0f));
  p.set("u_view2d", glm::mat3(1.0f));
  p.set("u_model", glm::vec3(1.0f));
  for (int c = 0; c < 4; ++c) {
    if (inputs[c].uniform.empty()) continue;
    p.set(inputs[c].uniform, c);
    if (inputs[c].kind == InputKind::texture)
      p.set(inputs[c].uniform + "Resolution", glm::vec2(in.channel_resolution[c][0], in.channel_resolution[c][1]));
  }
}

}  // namespace ms
