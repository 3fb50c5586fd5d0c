#include "shader/specialize.h"

#include <algorithm>
#include <cctype>
#include <cstring>
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

// Whether the table under `prefix` ("lights[", "materials[", "sky.") stays
// uniforms as a whole: an [[animation]] track drives something in it, or a
// live name is a whole entry ("materials[2]", no field).
bool held(const Scene& scene, const std::vector<std::string>& live, const std::string& prefix) {
  auto under = [&](const std::string& target) { return target.rfind(prefix, 0) == 0; };
  return std::any_of(live.begin(), live.end(),
                     [&](const std::string& l) { return under(l) && l.find('.', prefix.size()) == std::string::npos && prefix != "sky."; }) ||
         std::any_of(scene.animation.begin(), scene.animation.end(),
                     [&](const AnimationTrack& t) { return under(t.target); });
}

bool is_live(const std::vector<std::string>& live, const std::string& name) {
  return std::find(live.begin(), live.end(), name) != live.end();
}

// The uniform a live value is read from ("materials[1].color" ->
// uLive_materials_1_color; lights by their GLSL slot, live_uniform_name()),
// declared after a comment line naming it, which the viewer's log reads
// (not on the declaration's line: shader/scene_params.h reads those).
std::string live_uniform(const std::string& type, const std::string& uniform, const std::string& name) {
  return "// live value: " + name + "\nuniform " + type + " " + uniform + ";\n";
}

// The lights' values as constant tables, LIGHT_POS(i) and so on reading
// them (lighting.glsl); a one-light scene indexes them with a constant 0.
// A light value dragged in the panel (`live`: "lights[i].position" and so
// on, by GLSL slot) is read from its own uniform instead, chosen by index.
std::string folded_lights(const Scene& scene, const std::vector<std::string>& live, std::string& defines) {
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
  std::string uniforms;
  const struct { const char* macro; const char* table; const char* slot; const char* type; } slots[] = {
      {"LIGHT_POS(i)", "kLightPos[i]", "pos", "vec3"},
      {"LIGHT_COLOR(i)", "kLightColor[i]", "color", "vec3"},
      {"LIGHT_SIZE(i)", "kLightSize[i]", "size", "float"},
      {"LIGHT_ATTEN(i)", "kLightAtten[i]", "atten", "vec3"},
  };
  for (const auto& slot : slots) {
    std::string read = slot.table;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
      const std::string name = live_light_name(scene.lights[i], i, slot.slot);
      if (!is_live(live, name)) continue;
      const std::string u = live_uniform_name(name);
      uniforms += live_uniform(slot.type, u, name);
      read = "((i) == " + std::to_string(i) + " ? " + u + " : " + read + ")";
    }
    define(defines, slot.macro, read);
  }
  return "// The lights, folded (point: position; directional: unit travel direction).\n" + uniforms +
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
std::string folded_materials(const Scene& scene, bool checker, const std::vector<std::string>& live) {
  struct Field {
    const char* name;
    const char* key;  // the scene file's (and a live name's) field
    const char* type;
    std::function<std::string(const Material&)> literal;
    bool checker_only = false;
  };
  const std::vector<Field> fields = {
      {"color", "color", "vec3", [](const Material& m) { return vec3_literal(m.color); }},
      {"ka", "ambient", "float", [](const Material& m) { return glsl_float(m.ambient); }},
      {"kd", "diffuse", "float", [](const Material& m) { return glsl_float(m.diffuse); }},
      {"ks", "specular", "float", [](const Material& m) { return glsl_float(m.specular); }},
      {"shininess", "shininess", "float", [](const Material& m) { return glsl_float(m.shininess); }},
      {"reflectivity", "reflectivity", "float", [](const Material& m) { return glsl_float(m.reflectivity); }},
      {"color2", "color2", "vec3", [](const Material& m) { return vec3_literal(m.color2); }, true},
      {"patternScale", "pattern_scale", "float", [](const Material& m) { return glsl_float(m.pattern_scale); }, true},
      {"patternVelocity", "pattern_velocity", "vec3", [](const Material& m) { return vec3_literal(m.pattern_velocity); }, true},
  };
  size_t first_checker = 0;
  while (first_checker < scene.materials.size() && scene.materials[first_checker].pattern != Pattern::checker)
    ++first_checker;
  std::string uniforms, body;
  for (const Field& f : fields) {
    if (f.checker_only && !checker) continue;
    std::vector<std::string> values;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
      // A value dragged in the panel is read from its own uniform.
      const std::string name = "materials[" + std::to_string(i) + "]." + f.key;
      if (is_live(live, name)) {
        values.push_back(live_uniform_name(name));
        uniforms += live_uniform(f.type, values.back(), name);
        continue;
      }
      const bool stand_in = f.checker_only && scene.materials[i].pattern != Pattern::checker;
      values.push_back(f.literal(scene.materials[stand_in ? first_checker : i]));
    }
    body += "  m." + std::string(f.name) + " = " + select_by_id(f.type, values) + ";\n";
  }
  return "// The material table, folded: one constant per field where every material agrees.\n" + uniforms +
         "Material sceneMaterial(int id) {\n  Material m;\n" + body + "  return m;\n}\n";
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
  if (!scene.lights.empty() && !light_uniforms) out.constants += folded_lights(scene, live, d);

  // Materials: a folded sceneMaterial(), or the library's uniform lookup.
  // A table counts as a whole: one animated entry keeps all as uniforms.
  const bool material_uniforms = !fold || held(scene, live, "materials[");
  define(d, "MATERIAL_UNIFORMS", material_uniforms ? 1 : 0);
  if (!material_uniforms) out.constants += folded_materials(scene, f.checker, live);

  const bool sky_uniforms = !fold || held(scene, live, "sky.");
  define(d, "SKY_UNIFORMS", sky_uniforms ? 1 : 0);
  if (!sky_uniforms) {
    // The uniforms' own names, as constants; a live one stays the uniform.
    std::string sky = "// The sky, folded: the uniforms' names, as constants.\n";
    const struct { const char* key; const char* uniform; const glm::vec3& value; } fields[] = {
        {"horizon", "uSkyHorizon", scene.sky.horizon},
        {"zenith", "uSkyZenith", scene.sky.zenith},
        {"ambient", "uAmbient", scene.sky.ambient},
    };
    for (const auto& field : fields) {
      const std::string name = std::string("sky.") + field.key;
      sky += is_live(live, name) ? live_uniform("vec3", field.uniform, name)
                                 : "const vec3 " + std::string(field.uniform) + " = " + vec3_literal(field.value) + ";\n";
    }
    out.constants = sky + out.constants;
  }

  // Library functions: only those referenced (primitives.glsl, operators.glsl).
  define(d, "MS_LIBRARY_SUBSET", 1);
  for (const std::string& name : f.library) define(d, library_define(name), 1);
  return out;
}

std::string live_light_name(const Light& light, size_t i, const std::string& slot) {
  const std::string entry = "lights[" + std::to_string(i) + "].";
  if (slot == "pos") return entry + (light.kind == LightKind::point ? "position" : "direction");
  return entry + (slot == "atten" ? "attenuation" : slot);
}

std::string live_uniform_name(const std::string& name) {
  if (name.rfind("sky.", 0) == 0)
    return name == "sky.horizon" ? "uSkyHorizon" : name == "sky.zenith" ? "uSkyZenith" : "uAmbient";
  std::string u = "uLive_";
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) u += c;
    else if (u.back() != '_') u += '_';
  if (u.back() == '_') u.pop_back();
  // Lights by their GLSL slot: position and direction are both pos.
  for (const char* from : {"_position", "_direction"})
    if (const size_t at = u.rfind(from); at != std::string::npos && at + std::strlen(from) == u.size())
      u.replace(at, std::string::npos, "_pos");
  if (u.size() > 12 && u.compare(u.size() - 12, 12, "_attenuation") == 0) u.replace(u.size() - 12, 12, "_atten");
  return u;
}

std::vector<std::string> folded_differences(const Scene& a, const Scene& b) {
  std::vector<std::string> out;
  const size_t lights = std::max(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < lights; ++i) {
    if (i >= a.lights.size() || i >= b.lights.size() || a.lights[i].kind != b.lights[i].kind) {
      out.push_back("lights[" + std::to_string(i) + "]");
      continue;
    }
    // By GLSL slot: intensity is in the colour, the kind says position or direction.
    const GlslLight x = glsl_light(a.lights[i]), y = glsl_light(b.lights[i]);
    if (x.pos != y.pos) out.push_back(live_light_name(b.lights[i], i, "pos"));
    if (x.color != y.color) out.push_back(live_light_name(b.lights[i], i, "color"));
    if (x.size != y.size) out.push_back(live_light_name(b.lights[i], i, "size"));
    if (x.atten != y.atten) out.push_back(live_light_name(b.lights[i], i, "atten"));
  }
  const size_t materials = std::max(a.materials.size(), b.materials.size());
  for (size_t i = 0; i < materials; ++i) {
    const std::string entry = "materials[" + std::to_string(i) + "]";
    if (i >= a.materials.size() || i >= b.materials.size()) {
      out.push_back(entry);
      continue;
    }
    const Material &x = a.materials[i], &y = b.materials[i];
    const std::pair<const char*, bool> fields[] = {
        {"color", x.color != y.color},
        {"ambient", x.ambient != y.ambient},
        {"diffuse", x.diffuse != y.diffuse},
        {"specular", x.specular != y.specular},
        {"shininess", x.shininess != y.shininess},
        {"reflectivity", x.reflectivity != y.reflectivity},
        {"color2", x.color2 != y.color2},
        {"pattern_scale", x.pattern_scale != y.pattern_scale},
        {"pattern_velocity", x.pattern_velocity != y.pattern_velocity},
    };
    for (const auto& [field, differs] : fields)
      if (differs) out.push_back(entry + "." + field);
  }
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
