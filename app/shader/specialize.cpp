#include "shader/specialize.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <vector>

#include <glm/geometric.hpp>

#include "shader/assemble.h"

namespace ms {
namespace {

// Same float operations as render/uniforms.cpp always used.
float radians(float deg) { return deg * 3.14159265358979f / 180.0f; }

std::string vec3_literal(const glm::vec3& v) {
  return "vec3(" + glsl_float(v.x) + ", " + glsl_float(v.y) + ", " + glsl_float(v.z) + ")";
}

void define(std::string& out, const std::string& name, const std::string& value) {
  out += "#define " + name + " " + value + "\n";
}
void define(std::string& out, const std::string& name, int value) { define(out, name, std::to_string(value)); }

// Whether an [[animation]] track drives, or a live value is, anything under
// `prefix` ("lights[", "materials[", "sky."): such a table stays uniforms.
bool held(const Scene& scene, const std::vector<std::string>& live, const std::string& prefix) {
  auto under = [&](const std::string& target) { return target.rfind(prefix, 0) == 0; };
  return std::any_of(live.begin(), live.end(), under) ||
         std::any_of(scene.animation.begin(), scene.animation.end(),
                     [&](const AnimationTrack& t) { return under(t.target); });
}

bool same_light(const Light& a, const Light& b) {
  const GlslLight x = glsl_light(a), y = glsl_light(b);
  return x.pos == y.pos && x.color == y.color && x.size == y.size && x.atten == y.atten;
}

bool same_material(const Material& a, const Material& b) {
  return a.color == b.color && a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
         a.shininess == b.shininess && a.reflectivity == b.reflectivity && a.color2 == b.color2 &&
         a.pattern_scale == b.pattern_scale && a.pattern_velocity == b.pattern_velocity;
}

// The lights' values as constant tables, LIGHT_POS(i) and so on reading
// them (lighting.glsl); a one-light scene indexes them with a constant 0.
std::string folded_lights(const Scene& scene, std::string& defines) {
  std::string pos, color, size, atten;
  for (const Light& light : scene.lights) {
    const GlslLight g = glsl_light(light);
    const std::string sep = pos.empty() ? "" : ", ";
    pos += sep + vec3_literal(glm::vec3(g.pos));
    color += sep + vec3_literal(g.color);
    size += sep + glsl_float(g.size);
    atten += sep + vec3_literal(g.atten);
  }
  const std::string n = std::to_string(scene.lights.size());
  define(defines, "LIGHT_POS(i)", "kLightPos[i]");
  define(defines, "LIGHT_COLOR(i)", "kLightColor[i]");
  define(defines, "LIGHT_SIZE(i)", "kLightSize[i]");
  define(defines, "LIGHT_ATTEN(i)", "kLightAtten[i]");
  return "// The lights, folded (point: position; directional: unit travel direction).\n"
         "const vec3 kLightPos[" + n + "] = vec3[](" + pos + ");\n" +
         "const vec3 kLightColor[" + n + "] = vec3[](" + color + ");\n" +
         "const float kLightSize[" + n + "] = float[](" + size + ");\n" +
         "const vec3 kLightAtten[" + n + "] = vec3[](" + atten + ");\n";
}

// Value `id` of a per-material column, as cheap as the values allow: the
// constant itself when every material agrees, one select for a single
// change (`id <= 2 ? a : b`), else a constant array indexed by the (clamped)
// id: nested selects would become branches.
std::string select_by_id(const std::string& type, const std::vector<std::string>& values) {
  size_t change = 0;
  int changes = 0;
  for (size_t i = 0; i + 1 < values.size(); ++i)
    if (values[i] != values[i + 1]) {
      change = i;
      ++changes;
    }
  if (changes == 0) return values.front();
  if (changes == 1) return "id <= " + std::to_string(change) + " ? " + values.front() + " : " + values.back();
  std::string list;
  for (const std::string& v : values) list += (list.empty() ? "" : ", ") + v;
  return type + "[](" + list + ")[id]";
}

// Material sceneMaterial(int id) with every field folded. `pattern` is left
// out (a specialized shader tests MATERIAL_IS_CHECKER), and so are the
// checker's fields without a checker. Only checker materials read those
// fields, so the others take the first checker material's values: a single
// checker makes them constants.
std::string folded_materials(const Scene& scene, bool checker) {
  struct Field {
    const char* name;
    const char* type;
    std::function<std::string(const Material&)> literal;
    bool checker_only = false;
  };
  const std::vector<Field> fields = {
      {"color", "vec3", [](const Material& m) { return vec3_literal(m.color); }},
      {"ka", "float", [](const Material& m) { return glsl_float(m.ambient); }},
      {"kd", "float", [](const Material& m) { return glsl_float(m.diffuse); }},
      {"ks", "float", [](const Material& m) { return glsl_float(m.specular); }},
      {"shininess", "float", [](const Material& m) { return glsl_float(m.shininess); }},
      {"reflectivity", "float", [](const Material& m) { return glsl_float(m.reflectivity); }},
      {"color2", "vec3", [](const Material& m) { return vec3_literal(m.color2); }, true},
      {"patternScale", "float", [](const Material& m) { return glsl_float(m.pattern_scale); }, true},
      {"patternVelocity", "vec3", [](const Material& m) { return vec3_literal(m.pattern_velocity); }, true},
  };
  size_t first_checker = 0;
  while (first_checker < scene.materials.size() && scene.materials[first_checker].pattern != Pattern::checker)
    ++first_checker;
  std::string out = "// The material table, folded: one constant per field where every material agrees.\n";
  out += "Material sceneMaterial(int id) {\n  Material m;\n";
  for (const Field& f : fields) {
    if (f.checker_only && !checker) continue;
    std::vector<std::string> values;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
      const bool stand_in = f.checker_only && scene.materials[i].pattern != Pattern::checker;
      values.push_back(f.literal(scene.materials[stand_in ? first_checker : i]));
    }
    out += "  m." + std::string(f.name) + " = " + select_by_id(f.type, values) + ";\n";
  }
  return out + "  return m;\n}\n";
}

std::string library_define(const std::string& name) {
  std::string macro = "USE_";
  for (char c : name) macro += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return macro;
}

}  // namespace

const char* specialization_name(Specialization s) {
  switch (s) {
    case Specialization::generic: return "generic";
    case Specialization::uniforms: return "uniforms";
    case Specialization::folded: return "folded";
  }
  return "?";
}

GlslLight glsl_light(const Light& l) {
  GlslLight g;
  const bool point = l.kind == LightKind::point;
  g.pos = point ? glm::vec4(l.position, 1.0f) : glm::vec4(glm::normalize(l.direction), 0.0f);
  g.color = l.color * l.intensity;
  // A directional size is an angular diameter in degrees; GLSL wants the radius in radians.
  g.size = point ? l.size : radians(l.size) * 0.5f;
  g.atten = l.attenuation;
  return g;
}

Specialized specialize(const Scene& scene, const FeatureSet& f, Specialization mode,
                       const std::vector<std::string>& live) {
  Specialized out;
  out.quality = scene.quality;
  if (mode == Specialization::generic) return out;
  Quality& q = out.quality;
  q.reflections = f.reflective;
  q.bounces = f.max_bounces;
  q.shadows = f.shadows;
  q.ao = f.ao;

  const bool fold = mode == Specialization::folded;
  std::string& d = out.defines;
  define(d, "SPECIALIZED", 1);
  define(d, "USE_CHECKER", f.checker ? 1 : 0);
  if (f.checker) {
    std::string cond;
    for (size_t i = 0; i < scene.materials.size(); ++i)
      if (scene.materials[i].pattern == Pattern::checker)
        cond += std::string(cond.empty() ? "" : " || ") + "(id) == " + std::to_string(i);
    define(d, "MATERIAL_IS_CHECKER(id)", "(" + cond + ")");
  }

  // Lights: the count of each kind, each light's kind, and (folded, when no
  // animation drives a light) the values as constant tables.
  define(d, "NUM_POINT_LIGHTS", f.point_lights());
  define(d, "NUM_DIRECTIONAL_LIGHTS", f.directional_lights());
  std::string point_ids;
  for (size_t i = 0; i < f.lights.size(); ++i)
    if (f.lights[i] == LightKind::point) point_ids += std::string(point_ids.empty() ? "" : " || ") + "(i) == " + std::to_string(i);
  define(d, "LIGHT_IS_POINT(i)", "(" + (point_ids.empty() ? std::string("false") : point_ids) + ")");
  const bool light_uniforms = !scene.lights.empty() && (!fold || held(scene, live, "lights["));
  define(d, "LIGHT_UNIFORMS", light_uniforms ? 1 : 0);
  if (!scene.lights.empty() && !light_uniforms) out.constants += folded_lights(scene, d);

  // Materials: a folded sceneMaterial(), or the library's uniform lookup.
  // A table counts as a whole: one animated entry keeps all as uniforms.
  const bool material_uniforms = !fold || held(scene, live, "materials[");
  define(d, "MATERIAL_UNIFORMS", material_uniforms ? 1 : 0);
  if (!material_uniforms) out.constants += folded_materials(scene, f.checker);

  const bool sky_uniforms = !fold || held(scene, live, "sky.");
  define(d, "SKY_UNIFORMS", sky_uniforms ? 1 : 0);
  if (!sky_uniforms)
    out.constants = "// The sky, folded: the uniforms' names, as constants.\nconst vec3 uSkyHorizon = " +
                    vec3_literal(scene.sky.horizon) + ";\nconst vec3 uSkyZenith = " + vec3_literal(scene.sky.zenith) +
                    ";\nconst vec3 uAmbient = " + vec3_literal(scene.sky.ambient) + ";\n" + out.constants;

  // Library functions: only those referenced (primitives.glsl, operators.glsl).
  define(d, "MS_LIBRARY_SUBSET", 1);
  for (const std::string& name : f.library) define(d, library_define(name), 1);
  return out;
}

std::vector<std::string> folded_differences(const Scene& a, const Scene& b) {
  std::vector<std::string> out;
  const size_t lights = std::max(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < lights; ++i)
    if (i >= a.lights.size() || i >= b.lights.size() || !same_light(a.lights[i], b.lights[i]))
      out.push_back("lights[" + std::to_string(i) + "]");
  const size_t materials = std::max(a.materials.size(), b.materials.size());
  for (size_t i = 0; i < materials; ++i)
    if (i >= a.materials.size() || i >= b.materials.size() || !same_material(a.materials[i], b.materials[i]))
      out.push_back("materials[" + std::to_string(i) + "]");
  if (a.sky.horizon != b.sky.horizon) out.push_back("sky.horizon");
  if (a.sky.zenith != b.sky.zenith) out.push_back("sky.zenith");
  if (a.sky.ambient != b.sky.ambient) out.push_back("sky.ambient");
  return out;
}

std::uint64_t program_key(std::string_view vertex_source, std::string_view fragment_source) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a offset basis
  auto mix = [&h](std::string_view s) {
    for (unsigned char c : s) {
      h ^= c;
      h *= 1099511628211ull;  // FNV prime
    }
  };
  mix(vertex_source);
  mix(std::string_view("\0", 1));  // "ab"+"c" and "a"+"bc" must differ
  mix(fragment_source);
  return h;
}

}  // namespace ms
