#include "scene/load.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "io/image_io.h"
#include "io/input_file.h"
#include "scene/load_passes.h"
#include "core/error.h"
#include "scene/animation.h"
#include "scene/load_geometry.h"
#include "scene/graph_animation.h"
#include "scene/graph_scene.h"
#include "scene/load_post.h"
#include "scene/overrides.h"
#include "scene/quality.h"
#include "scene/quality_fields.h"
#include "scene/schema.h"
#include "core/suggest.h"
#include "scene/toml_guard.h"
#include "scene/toml_read.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Squared length below which a direction has no usable direction.
constexpr double kTinySq = 1e-12;

// Enum spellings, in the order of the enum's values.
constexpr std::string_view kTonemaps[] = {"none", "reinhard", "aces"};
constexpr std::string_view kLightKinds[] = {"point", "directional"};
constexpr std::string_view kPatterns[] = {"none", "checker"};

[[noreturn]] void fail_parse(const Reader& r, const toml::parse_error& e) {
  r.fail(static_cast<int>(e.source().begin.line), {}, "invalid TOML: " + printable(e.description(), 200));
}

// toml++ reports syntax errors by exception or by result, depending on how
// it was configured (TOML_EXCEPTIONS); both end in the same ms::Error. The
// Debian shared library is built with exceptions (namespace toml::v3::ex),
// so the second branch only matters for a header-only build without them.
toml::table parse_toml(std::string_view text, const Reader& r) {
  check_toml_key_depth(text, r.file());  // toml++ recurses per dotted key component
#if TOML_EXCEPTIONS
  try {
    return toml::parse(text, std::string_view{r.file()});
  } catch (const toml::parse_error& e) {
    fail_parse(r, e);
  }
#else
  toml::parse_result result = toml::parse(text, std::string_view{r.file()});
  if (!result) fail_parse(r, result.error());
  return std::move(result).table();
#endif
}

// A section [name] that is a plain struct of Fields.
template <class T, std::size_t N>
const toml::table* read_section(const Reader& r, const Schema& schema, const toml::table& root,
                                std::string_view name, const Field<T> (&fields)[N], T& out) {
  const toml::table* t = r.table(root, {}, name);
  if (t) {
    schema.check(r, *t, name, name);
    r.read_fields(*t, name, fields, out);
  }
  return t;
}

double length_sq(const glm::vec3& v) { return glm::dot(glm::dvec3(v), glm::dvec3(v)); }

void check_camera(const Reader& r, const toml::table* t, const Camera& c) {
  auto line = [&](std::string_view key) { return t ? Reader::line_of(*t, key) : 0; };
  const glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.position);
  const glm::dvec3 up(c.up);
  if (length_sq(c.up) <= kTinySq) r.fail(line("up"), "camera.up", "'camera.up' must not be zero-length");
  if (glm::dot(view, view) <= kTinySq)
    r.fail(line("target"), "camera.target", "'camera.target' must differ from 'camera.position'",
           "the camera looks from position towards target");
  // An up vector along the view direction leaves the camera's roll undefined.
  const glm::dvec3 side = glm::cross(view, up);
  if (glm::dot(side, side) <= 1e-8 * glm::dot(view, view) * glm::dot(up, up))
    r.fail(line("up"), "camera.up", "'camera.up' is parallel to the view direction",
           "set camera.up to another direction; it defaults to [0, 1, 0]");
}

Light read_light(const Reader& r, const Schema& schema, const toml::table& t, const std::string& path) {
  Light light;
  schema.check(r, t, "lights", path);
  r.read_enum(t, path, "type", kLightKinds, light.kind);
  // A key the light's type ignores is a mistake, not a no-op.
  const bool point = light.kind == LightKind::point;
  for (std::string_view key : {"position", "direction", "attenuation"}) {
    const bool used = point ? key != "direction" : key == "direction";
    if (!used && t.get(key))
      r.fail(Reader::line_of(t, key), join_key(path, key),
             quote(join_key(path, key)) + " does nothing for a " + (point ? "point" : "directional") + " light",
             point ? "remove it, or set type = \"directional\"" : "remove it, or set type = \"point\"");
  }
  r.read_fields(t, path, kLightFields, light);
  if (!point && length_sq(light.direction) <= kTinySq)
    r.fail(Reader::line_of(t, "direction"), path + ".direction", quote(path + ".direction") + " must not be zero-length");
  // A directional size is an angular diameter: 180 degrees and up is no disc.
  if (!point && light.size >= 180.0f)
    r.fail(Reader::line_of(t, "size"), path + ".size",
           quote(path + ".size") + " must be in [0, 180) for a directional light, got " + format_number(light.size),
           "it is the angular diameter in degrees; the sun is about 0.53");
  if (point && light.attenuation.x + light.attenuation.y + light.attenuation.z <= 0.0f)
    r.fail(Reader::line_of(t, "attenuation"), path + ".attenuation", quote(path + ".attenuation") + " must not be all zero",
           "use [1, 0, 0] for no falloff");
  return light;
}

// Material names become GLSL macros MAT_<NAME>, so they must be identifiers
// that GLSL accepts: no '__' anywhere in MAT_<NAME> (reserved).
void check_material_name(const Reader& r, const toml::table& t, const std::string& key, const std::string& name) {
  const int line = Reader::line_of(t, "name");
  const bool ident = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                     std::all_of(name.begin(), name.end(), [](char c) {
                       return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
                     });
  if (!ident)
    r.fail(line, key, quote(key) + " = " + quote(name) + " is not an identifier",
           "use letters, digits and '_', not starting with a digit");
  if (name[0] == '_' || name.find("__") != std::string::npos)
    r.fail(line, key, quote(key) + " = " + quote(name) + " would make a GLSL name with '__', which GLSL reserves",
           "do not start it with '_' or use '__'");
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void read_materials(const Reader& r, const Schema& schema, const toml::table& root, Scene& scene) {
  const auto tables = r.tables(root, {}, "materials");
  // A graph's materials default from the names it uses (scene/graph_build.h).
  const toml::table* st = root["scene"].as_table();
  if (tables.empty() && st && st->contains("graph")) return;
  if (tables.empty())
    r.fail(root.get("materials") ? Reader::line_of(root, "materials") : 0, "materials", "the scene defines no materials",
           "add at least one [[materials]] table with a name");
  if (tables.size() > kMaxMaterials)
    r.fail(Reader::line_of(*tables[kMaxMaterials]), "materials",
           "too many materials: " + std::to_string(tables.size()) + " (at most " + std::to_string(kMaxMaterials) + ")");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string path = "materials[" + std::to_string(i) + "]", key = path + ".name";
    Material m;
    schema.check(r, t, "materials", path);
    if (!r.read(t, path, "name", m.name))
      r.fail(Reader::line_of(t), key, "missing required key " + quote(key), "every material needs a name, e.g. name = \"floor\"");
    check_material_name(r, t, key, m.name);
    for (std::size_t j = 0; j < i; ++j)
      if (upper(scene.materials[j].name) == upper(m.name))
        r.fail(Reader::line_of(t, "name"), key, "duplicate material name " + quote(m.name),
               "materials[" + std::to_string(j) + "] is already " + quote(scene.materials[j].name) +
                   "; names are case-insensitive, as GLSL sees MAT_" + upper(m.name));
    r.read_enum(t, path, "pattern", kPatterns, m.pattern);
    r.read_fields(t, path, kMaterialFields, m);
    scene.materials.push_back(std::move(m));
  }
}

// [quality]: the preset first (default balanced), then every key the file
// sets, which overrides the preset and is remembered as explicit (so that
// --preset can re-base the scene and keep it).
void read_quality(const Reader& r, const Schema& schema, const toml::table& root, Quality& q) {
  const toml::table* t = r.table(root, {}, "quality");
  if (!t) return;
  schema.check(r, *t, "quality", "quality");
  std::string preset = q.preset;
  if (r.read(*t, "quality", "preset", preset)) {
    const auto& names = quality_preset_names();
    if (std::find(names.begin(), names.end(), preset) == names.end()) {
      const std::vector<std::string_view> views(names.begin(), names.end());
      const std::string hint = did_you_mean(preset, views);
      r.fail(Reader::line_of(*t, "preset"), "quality.preset", "unknown value " + quote(preset) + " for 'quality.preset'",
             hint.empty() ? "use fast, balanced, reference or textbook" : hint);
    }
  }
  q = preset_quality(preset);
  r.read_fields(*t, "quality", kQualityFields, q);
  for (auto&& [k, v] : *t)
    if (k.str() != "preset") q.explicit_keys.emplace_back(k.str());
}

// `scene.<key>` (map or shadertoy) relative to the scene file's folder; it
// must be a readable file.
fs::path resolve_glsl(const Reader& r, const toml::table& t, const fs::path& display_path, const std::string& key) {
  const std::string dotted = "scene." + key;
  std::string file;
  r.read(t, "scene", key, file);
  const int line = Reader::line_of(t, key);
  if (file.empty()) r.fail(line, dotted, quote(dotted) + " must not be empty");
  const fs::path resolved = (display_path.parent_path() / fs::path(file)).lexically_normal();
  // Opening a FIFO or a device would block (or read forever): files only.
  if (const std::string why = input_file_problem(resolved); !why.empty())
    r.fail(line, dotted, key + " file " + quote(resolved.string()) + " " + why,
           why == "not found" ? quote(dotted) + " is relative to the scene file" : "");
  return resolved;
}

// [sky] environment: an .exr or .hdr file next to the scene; rotation and
// intensity only mean something with one.
void read_environment(const Reader& r, const toml::table& t, const fs::path& display_path, Sky& sky) {
  if (!t.contains("environment")) {
    for (const char* key : {"rotation", "intensity"})
      if (t.contains(key))
        r.fail(Reader::line_of(t, key), std::string("sky.") + key, std::string("sky.") + key + " has no effect without sky.environment",
               "set environment = \"sky.exr\" (an equirectangular EXR or HDR), or drop the key");
    return;
  }
  std::string file;
  r.read(t, "sky", "environment", file);
  const int line = Reader::line_of(t, "environment");
  if (file.empty()) r.fail(line, "sky.environment", "'sky.environment' must not be empty");
  const fs::path resolved = (display_path.parent_path() / fs::path(file)).lexically_normal();
  if (!is_float_image_name(resolved))
    r.fail(line, "sky.environment", "environment " + quote(resolved.string()) + " is not an .exr or .hdr file",
           "an equirectangular high-dynamic-range image");
  if (const std::string why = input_file_problem(resolved); !why.empty())
    r.fail(line, "sky.environment", "environment file " + quote(resolved.string()) + " " + why,
           why == "not found" ? "'sky.environment' is relative to the scene file" : "");
  sky.environment = resolved;
}

// Exactly one of scene.map (an SDF scene), scene.graph (a CSG graph) and
// scene.shadertoy (a Shadertoy shader given size, time and spp by this file).
void resolve_sources(const Reader& r, const toml::table* t, const fs::path& display_path,
                     const std::vector<fs::path>& roots, Scene& scene) {
  std::vector<std::string> given;
  for (const char* k : {"map", "graph", "shadertoy"})
    if (t && t->contains(k)) given.emplace_back(k);
  if (given.size() > 1)
    r.fail(Reader::line_of(*t, given[1]), "scene." + given[1],
           "'scene." + given[0] + "' and 'scene." + given[1] + "' exclude each other",
           "a scene is an SDF map, a CSG graph or a Shadertoy shader");
  if (scene.passes) {
    if (!given.empty())
      r.fail(Reader::line_of(*t, given[0]), "scene." + given[0],
             "[[passes]] name the shader's files: drop 'scene." + given[0] + "'");
    return;
  }
  if (given.empty())
    r.fail(t ? Reader::line_of(*t) : 0, "scene.map", "the scene names no source: one of 'scene.map', 'scene.graph' or 'scene.shadertoy' is required",
           "add map = \"<file>.glsl\" under [scene]: the GLSL file that defines vec2 map(vec3 p); or graph = \"<file>.json\"");
  if (given[0] == "shadertoy") scene.shadertoy_file = resolve_glsl(r, *t, display_path, "shadertoy");
  else if (given[0] == "graph") attach_graph(r, *t, display_path, roots, scene);  // scene/graph_scene.h
  else scene.map_file = resolve_glsl(r, *t, display_path, "map");
}

// A Shadertoy shader draws everything itself: of the scene file it takes
// only [scene] and [render]'s size, samples, time and exposure. Anything
// else would be silently dropped, so it is an error at its line.
void check_shadertoy_wrapper(const Reader& r, const toml::table& root) {
  const std::string hint =
      "a Shadertoy wrapper takes [scene], [render] width, height, spp, time, exposure, [shadertoy] and [[passes]]";
  for (auto&& [k, v] : root) {
    const std::string key(k.str());
    if (key == "scene" || key == "render" || key == "shadertoy" || key == "passes") continue;
    int line = static_cast<int>(v.source().begin.line);
    if (const toml::array* a = v.as_array(); a && !a->empty()) line = static_cast<int>((*a)[0].source().begin.line);
    r.fail(line, key, quote(key) + " has no effect on a Shadertoy shader", hint);
  }
  if (const toml::table* render = root["render"].as_table(); render && render->contains("tonemap"))
    r.fail(Reader::line_of(*render, "tonemap"), "render.tonemap",
           "'render.tonemap' has no effect on a Shadertoy shader", "its output is display-referred already");
}

// Every table and key of a parsed scene file, validated, into a Scene.
Scene read_scene(const Reader& r, const toml::table& root, const fs::path& display_path,
                 const std::vector<fs::path>& roots) {
  const Schema schema;
  r.check_keys(root, {}, schema.top, [&](std::string_view key) { return schema.elsewhere({}, key); });

  Scene scene;
  scene.file = display_path;
  scene.name = display_path.stem().string();
  const toml::table* st = r.table(root, {}, "scene");
  if (st) {
    schema.check(r, *st, "scene", "scene");
    r.read(*st, "scene", "name", scene.name);
  }
  const bool wrapper = (st && st->contains("shadertoy")) || root.contains("passes");
  if (wrapper) check_shadertoy_wrapper(r, root);
  if (!wrapper && root.contains("shadertoy"))
    r.fail(root["shadertoy"].as_table() ? Reader::line_of(*root["shadertoy"].as_table()) : 0, "shadertoy",
           "[shadertoy] settings need a Shadertoy shader", "[scene] shadertoy = \"x.glsl\" (or .json), or [[passes]]");
  read_shadertoy_settings(r, root, display_path, scene.shadertoy);
  scene.passes = read_passes(r, root, display_path, scene.shadertoy);
  const toml::table* camera = read_section(r, schema, root, "camera", kCameraFields, scene.camera);
  check_camera(r, camera, scene.camera);
  if (const toml::table* t = read_section(r, schema, root, "render", kRenderFields, scene.render))
    r.read_enum(*t, "render", "tonemap", kTonemaps, scene.render.tonemap);
  if (const toml::table* sky = read_section(r, schema, root, "sky", kSkyFields, scene.sky))
    read_environment(r, *sky, display_path, scene.sky);
  read_quality(r, schema, root, scene.quality);

  const auto lights = r.tables(root, {}, "lights");
  if (lights.size() > kMaxLights)
    r.fail(Reader::line_of(*lights[kMaxLights]), "lights",
           "too many lights: " + std::to_string(lights.size()) + " (at most " + std::to_string(kMaxLights) + ")");
  for (std::size_t i = 0; i < lights.size(); ++i)
    scene.lights.push_back(read_light(r, schema, *lights[i], "lights[" + std::to_string(i) + "]"));
  // A Shadertoy scene has no map() and so needs no materials.
  if (!wrapper || root.contains("materials")) read_materials(r, schema, root, scene);
  const CheckKeys check = [&](const toml::table& t, std::string_view section, const std::string& path) {
    schema.check(r, t, section, path);
  };
  read_planes(r, check, root, scene);
  read_bounds(r, check, root, scene.bounds);
  read_post(r, root, scene.bloom);  // scene/load_post.h
  // After lights and materials: a track's target must name one that exists;
  // a graph node's (scene/graph_animation.h) once the graph is read.
  const auto tracks = r.tables(root, {}, "animation");
  scene.animation.resize(tracks.size());
  const auto read_tracks = [&](bool graph) {
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      if (is_graph_target((*tracks[i])["target"].value_or(std::string())) != graph) continue;
      const std::string path = "animation[" + std::to_string(i) + "]";
      schema.check(r, *tracks[i], "animation", path);
      scene.animation[i] = read_animation_track(r, *tracks[i], path, scene);
    }
  };
  read_tracks(false);

  // Last, so a broken scene file is reported before a missing map file.
  resolve_sources(r, st, display_path, roots, scene);
  read_tracks(true);
  return scene;
}

}  // namespace

Scene parse_scene(std::string_view toml_text, const fs::path& display_path, const SceneOverrides& overrides,
                  const std::vector<fs::path>& roots) {
  const Reader r(display_path.string());
  toml::table root = parse_toml(toml_text, r);
  // Before validation, so an override meets every check the file does.
  const std::vector<std::string> keys = apply_overrides(root, overrides);
  Scene scene;
  try {
    scene = read_scene(r, root, display_path, roots);
  } catch (const Error& e) {
    if (overrides.empty()) throw;
    throw Error(blame_override(e.info(), overrides, keys));
  }
  drop_overridden_tracks(scene, overrides, keys);
  return scene;
}

Scene load_scene(const fs::path& toml_path, const SceneOverrides& overrides, const std::vector<fs::path>& roots) {
  return parse_scene(read_input_file(toml_path, "scene file"), toml_path, overrides, roots);
}

}  // namespace ms
