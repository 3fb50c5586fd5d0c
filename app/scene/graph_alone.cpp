#include "scene/graph_alone.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "core/format.h"
#include "io/input_file.h"
#include "io/json_doc.h"
#include "scene/graph_build.h"
#include "scene/graph_scene.h"

namespace ms {

namespace fs = std::filesystem;

namespace {

// Whether the top-level object has any of `wanted` as a member name: a
// scan of the text, not a parse (a Shadertoy download may be megabytes,
// and its own reader reports its syntax errors).
bool top_level_has(std::string_view t, std::initializer_list<std::string_view> wanted) {
  int depth = 0;
  bool want_key = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '"') {
      std::string s;
      std::size_t j = i + 1;
      for (; j < t.size() && t[j] != '"'; ++j) {
        if (t[j] == '\\') ++j;  // an escaped character never ends the string
        else s += t[j];
      }
      if (depth == 1 && want_key && std::find(wanted.begin(), wanted.end(), s) != wanted.end()) return true;
      if (depth == 1) want_key = false;
      i = j;
    } else if (c == '{' || c == '[') {
      want_key = ++depth == 1 && c == '{';
    } else if (c == '}' || c == ']') {
      --depth;
    } else if (c == ',' && depth == 1) {
      want_key = true;
    }
  }
  return false;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool identifier(const std::string& s) {
  return !s.empty() && !std::isdigit(static_cast<unsigned char>(s[0])) && s[0] != '_' &&
         s.find("__") == std::string::npos &&
         std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Named materials' colours, in turn: distinct enough to tell parts apart.
constexpr float kPalette[][3] = {{0.85f, 0.25f, 0.20f}, {0.25f, 0.50f, 0.85f}, {0.30f, 0.70f, 0.35f},
                                 {0.90f, 0.70f, 0.20f}, {0.60f, 0.35f, 0.75f}, {0.20f, 0.70f, 0.70f},
                                 {0.90f, 0.50f, 0.25f}, {0.55f, 0.55f, 0.60f}};

// Every light and the camera are placed from the box alone, so the view is
// the same whatever the box's size and position.
Camera framing(const GraphBox& box, float& far) {
  const glm::dvec3 lo(box.min), hi(box.max), centre = (lo + hi) * 0.5;
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-6 * std::max(1.0, glm::length(centre)));
  Camera c;
  // The bounding sphere inside the vertical field of view (the narrower
  // one for an image at least as wide as tall), with a margin.
  const double distance = 1.15 * radius / std::sin(glm::radians(0.5 * c.fov_deg));
  // A 3/4 view from above: 35 degrees round from the front, 25 up.
  const double az = glm::radians(35.0), el = glm::radians(25.0);
  const glm::dvec3 dir(std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el));
  c.position = glm::vec3(centre + distance * dir);
  c.target = glm::vec3(centre);
  far = static_cast<float>(4.0 * (distance + radius));  // the hits fade into the sky from 0.6 of it
  return c;
}

std::vector<Light> studio_lights() {
  Light key;
  key.kind = LightKind::directional;
  key.direction = glm::normalize(glm::vec3(0.45f, -1.0f, 0.55f));  // from above, left of the camera
  key.color = {1.0f, 0.96f, 0.9f};
  key.intensity = 1.4f;
  key.size = 2.0f;  // degrees: soft-edged shadows
  Light fill;
  fill.kind = LightKind::directional;
  fill.direction = glm::normalize(glm::vec3(-0.7f, -0.35f, 0.6f));  // low, from the camera's right
  fill.color = {0.8f, 0.87f, 1.0f};
  fill.intensity = 0.35f;
  fill.size = 30.0f;  // a broad source: its shadows are faint
  return {key, fill};
}

// A checker floor just under the box, its squares a round number of world
// units near a tenth of the box's size.
void add_floor(const GraphBox& box, Scene& scene) {
  if (scene.materials.size() >= kMaxMaterials)
    fail_input("too many materials: the graph names " + std::to_string(kMaxMaterials - 1) +
                   ", and with the default and the floor's that passes " + std::to_string(kMaxMaterials),
               scene.file.string(), 1, {},
               "name at most " + std::to_string(kMaxMaterials - 2) + ", or use a scene .toml");
  Material floor;
  floor.name = "floor";
  for (int i = 1; std::any_of(scene.materials.begin(), scene.materials.end(),
                              [&](const Material& m) { return upper(m.name) == upper(floor.name); });
       ++i)
    floor.name = "floor_" + std::to_string(i);
  floor.color = glm::vec3(0.8f);
  floor.color2 = glm::vec3(0.3f);
  floor.pattern = Pattern::checker;
  const double size = glm::length(glm::dvec3(box.max) - glm::dvec3(box.min));
  floor.pattern_scale = static_cast<float>(std::pow(10.0, std::floor(std::log10(std::max(size, 1e-30) * 0.5))));
  floor.diffuse = 0.9f;
  floor.specular = 0.2f;
  floor.shininess = 16.0f;
  Plane p;
  p.normal = {0.0f, 1.0f, 0.0f};
  p.offset = -static_cast<float>(box.min.y - 0.005 * size);  // dot(p, n) + offset = 0 at the floor
  p.material = floor.name;
  p.material_id = static_cast<int>(scene.materials.size());
  scene.materials.push_back(std::move(floor));
  scene.planes.push_back(std::move(p));
}

}  // namespace

JsonInput json_input_kind(std::string_view text, const std::string& display) {
  const std::size_t at = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (looks_like_json(text) && text[at] == '[') return JsonInput::shadertoy;
  if (looks_like_json(text)) {
    if (top_level_has(text, {"root"})) return JsonInput::graph;
    if (top_level_has(text, {"Shader", "renderpass", "Error"})) return JsonInput::shadertoy;
  }
  fail_input("neither a scene graph nor Shadertoy JSON", display, 1, {},
             "a graph file is {\"root\": NODE} (docs/scene-graph.md); Shadertoy JSON is {\"Shader\": {...}} or an "
             "array of shaders");
}

bool is_graph_file(const fs::path& file) {
  if (!input_file_problem(file).empty()) return false;
  // The first bytes turn an image away before it is read whole; a head of
  // blanks alone says nothing yet.
  char head[64] = {};
  std::ifstream in(file, std::ios::binary);
  in.read(head, sizeof head);
  const std::string_view h(head, static_cast<std::size_t>(in.gcount()));
  if (h.find_first_not_of(" \t\r\n\xEF\xBB\xBF") != std::string_view::npos && !looks_like_json(h)) return false;
  const std::string text = read_input_file(file, "input file");
  return looks_like_json(text) && json_input_kind(text, file.string()) == JsonInput::graph;
}

std::vector<Material> graph_default_materials(const JsonDoc& doc, const std::string& display,
                                              const std::string& prefix) {
  std::vector<Material> out(1);
  out[0].name = "default";
  for (int i = 0; i < static_cast<int>(doc.values.size()); ++i) {
    const JsonValue& v = doc.at(i);
    if (v.kind != JsonKind::string || v.parent == -1 || doc.at(v.parent).kind != JsonKind::object ||
        doc.key(i) != "material")
      continue;  // a 'material' that is not a string is the builder's to refuse
    const std::string name(doc.text(i));
    const auto same =
        std::find_if(out.begin(), out.end(), [&](const Material& m) { return upper(m.name) == upper(name); });
    if (same != out.end() && same->name == name) continue;
    const auto fail = [&](const std::string& what, const std::string& hint) {
      fail_input(what, display, v.line, prefix + doc.pointer(i), hint);
    };
    if (!identifier(name))
      fail("material " + quote(name) + " is not a name GLSL can take as MAT_" + upper(name),
           "use letters, digits and '_', not starting with a digit or '_', without '__'");
    if (same != out.end())
      fail("material " + quote(name) + " and " + quote(same->name) + " are one name to GLSL (MAT_" + upper(name) + ")",
           same - out.begin() == 0 ? "'default' is the material of nodes that name none" : "spell them alike");
    if (out.size() >= kMaxMaterials)
      fail("too many materials: the graph names more than " + std::to_string(kMaxMaterials - 1),
           "at most " + std::to_string(kMaxMaterials) + " with the default");
    Material m;
    m.name = name;
    const float* c = kPalette[(out.size() - 1) % (sizeof kPalette / sizeof kPalette[0])];
    m.color = {c[0], c[1], c[2]};
    out.push_back(std::move(m));
  }
  return out;
}

Scene graph_alone_scene(const fs::path& file) {
  Scene scene;
  scene.file = file;
  scene.name = file.stem().string();
  scene.graph_alone = true;
  SceneGraph g = load_graph_file(file, scene.materials);  // the materials: its defaults
  const GraphNode& root = g.root_node();
  scene.bounds = graph_bounds(root.box);
  scene.quality.lipschitz = root.lipschitz;
  scene.quality.lipschitz_derived = true;
  float far = 0.0f;
  scene.camera = framing(root.box, far);
  if (far > scene.quality.max_distance) {
    scene.quality.max_distance = far;
    scene.quality.explicit_keys.push_back("max_distance");  // a --preset keeps it
  }
  scene.lights = studio_lights();
  add_floor(root.box, scene);
  scene.graph = std::make_shared<const SceneGraph>(std::move(g));
  return scene;
}

void drop_floor(Scene& scene) {
  if (!scene.graph_alone || scene.planes.empty()) return;
  scene.materials.erase(scene.materials.begin() + scene.planes.back().material_id);
  scene.planes.pop_back();
}

}  // namespace ms
