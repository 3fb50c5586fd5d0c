// Scene: everything a scene file says, validated, in plain structs with
// sensible defaults. Loaded by scene/load.h; read by shader/ and render/.
// No GL here.
#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/graph.h"
#include "scene/project.h"

namespace ms {

struct Camera {
  glm::vec3 position{0.0f, 1.0f, -5.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_deg = 45.0f;  // vertical field of view, degrees, in (0, 180)
};

enum class LightKind { point, directional };

struct Light {
  LightKind kind = LightKind::point;
  glm::vec3 position{0.0f, 5.0f, 0.0f};   // point lights
  glm::vec3 direction{0.0f, -1.0f, 0.0f}; // directional: the direction light travels
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  // Penumbra size: a point light's radius in world units; a directional
  // light's angular diameter in degrees (the sun is about 0.53).
  float size = 0.0f;
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // 1 / (c + l*d + q*d^2); point only
};

enum class Pattern { none, checker };

struct Material {
  std::string name;              // GLSL sees it as MAT_<NAME upper-cased>
  glm::vec3 color{0.8f};         // albedo
  float ambient = 1.0f;          // Ka
  float diffuse = 1.0f;          // Kd
  float specular = 0.5f;         // Ks
  float shininess = 32.0f;       // Blinn-Phong exponent s
  float reflectivity = 0.0f;     // Fresnel F0; > 0 makes the material a mirror
  Pattern pattern = Pattern::none;
  glm::vec3 color2{0.1f};        // second checker colour
  float pattern_scale = 1.0f;    // checker cell size, world units
  glm::vec3 pattern_velocity{0.0f};  // checker offset per second (animated checker)
};

enum class Tonemap { none, reinhard, aces };

// The defaults are the `balanced` preset; scene/quality.h defines the others
// (fast, reference, textbook) in one place.
struct Quality {
  int max_steps = 255;
  float max_distance = 100.0f;
  float hit_tolerance = 0.01f;  // hit when d < max(hit_epsilon, hit_tolerance * pixel footprint at t)
  float hit_epsilon = 1e-4f;    // absolute floor of the hit tolerance
  float lipschitz = 1.0f;       // the scene SDF's Lipschitz bound (step = d / L)
  bool lipschitz_derived = false;  // lipschitz came from the scene graph: a preset keeps it
  float omega = 1.0f;           // over-relaxation of the primary/reflection march, [1, 2); 1: plain
  int shadow_steps = 64;
  int ao_taps = 5;
  int bounces = 1;              // reflection bounces
  bool shadows = true;
  bool ao = true;
  bool reflections = true;
  bool checker_filter = true;
  bool bounds = true;           // march map() only inside the scene's [bounds], when it has one
  bool analytic_planes = true;  // intersect [[planes]] exactly; false marches them (the textbook way)
  std::string preset = "balanced";          // the preset these values started from
  std::vector<std::string> explicit_keys;   // [quality] keys the file set: they override any preset
};

// An infinite plane dot(p, normal) + offset = 0, solid below, intersected
// exactly instead of marched ([[planes]]; docs/scene-format.md).
struct Plane {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit length after loading
  float offset = 0.0f;
  std::string material;                // a [[materials]] name
  int material_id = 0;                 // its index
};

// A volume that contains everything map() draws (planes excluded): rays
// march map() only where they are inside it ([bounds]).
enum class BoundsKind { none, sphere, box };
struct Bounds {
  BoundsKind kind = BoundsKind::none;
  glm::vec3 center{0.0f};  // sphere
  float radius = 0.0f;
  glm::vec3 min{0.0f};     // box
  glm::vec3 max{0.0f};
};

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int spp = 1;
  float time = 0.0f;
  float exposure = 1.0f;
  Tonemap tonemap = Tonemap::aces;
};

// [post.bloom] (docs/post.md): values above `threshold` in the linear image,
// blurred at `scale` of its resolution, added back before exposure.
struct Bloom {
  bool enabled = false;    // the table is present (and --disable bloom not given)
  float threshold = 1.0f;  // linear radiance, luminance above which a pixel blooms
  float intensity = 0.5f;  // multiplier of the blurred image added back
  float radius = 8.0f;     // Gaussian sigma of the whole blur, full-resolution pixels
  float scale = 0.3f;      // resolution of the blur targets, [0.05, 1]
  int passes = 2;          // H+V blur passes, the sigma split between them
  bool exr = false;        // an .exr output has bloom too (else the pre-bloom image)
};

struct Sky {
  glm::vec3 horizon{0.70f, 0.80f, 0.95f};
  glm::vec3 zenith{0.25f, 0.45f, 0.85f};
  glm::vec3 ambient{0.15f, 0.17f, 0.20f};  // Ia, ambient light
  // [sky] environment: an equirectangular EXR or HDR seen where rays escape
  // and lighting the ambient term by its diffuse irradiance instead of the
  // gradient and `ambient` (render/environment.h). Empty: the gradient.
  std::filesystem::path environment;
  float rotation = 0.0f;   // degrees about +y
  float intensity = 1.0f;  // scales the map (and so its irradiance)
  // The map's irradiance as 9 spherical-harmonic coefficients, E(n) / pi;
  // computed when the map is loaded (render/environment.h), not read.
  std::array<glm::vec3, 9> irradiance{};
};

enum class Interpolation { linear, smooth };

// One keyframed value, [[animation]] in the scene file (docs/scene-format.md).
// scene/animation.h evaluates it; the static fields above hold the values at
// no particular time and are what an unanimated render uses.
struct AnimationTrack {
  std::string target;          // as written and checked: "camera.position", "lights[0].intensity"
  Interpolation interpolation = Interpolation::linear;
  int arity = 1;               // values per key: 1 (float) or 3 (vec3)
  std::vector<double> times;   // seconds, strictly increasing, at least one
  std::vector<double> values;  // times.size() * arity; double so key values stay exact
  int line = 0;                // of the [[animation]] table, for errors at render time
  // A graph node's value (target "graph.NAME.KEY"): the numbers it sets in
  // Scene::graph_doc (scene/graph_animation.h); empty for every other target.
  std::vector<int> graph_values;
};

struct GraphDoc;

// At most this many [[lights]] and [[materials]] (scene/load.cpp refuses
// more): the shaders' uniform arrays and the host's name tables are sized by them.
inline constexpr std::size_t kMaxLights = 8;
inline constexpr std::size_t kMaxMaterials = 32;

struct Scene {
  std::filesystem::path file;      // the .toml, as given
  std::filesystem::path map_file;  // the GLSL with vec2 map(vec3 p), resolved
  std::filesystem::path shadertoy_file;  // instead of map_file: a Shadertoy shader (.glsl or .json), resolved
  // Instead of both: the passes of a [[passes]] wrapper (docs/scene-format.md).
  std::shared_ptr<const ShaderProject> passes;
  // Instead of map_file: a CSG graph ([scene] graph, docs/scene-graph.md).
  std::shared_ptr<const SceneGraph> graph;
  bool bounds_declared = false;    // [bounds] came from the file (else, with a graph, from its box)
  // A graph file on its own: camera, lights, floor and materials are
  // defaults (scene/graph_alone.h).
  bool graph_alone = false;
  ShadertoySettings shadertoy;     // [shadertoy]: media, mouse, fps
  std::string name;
  Camera camera;
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<Plane> planes;       // analytic, not part of map()
  Bounds bounds;                   // where map() is marched; none: everywhere
  Quality quality;
  RenderSettings render;
  Sky sky;
  Bloom bloom;                     // [post.bloom]
  std::vector<AnimationTrack> animation;  // applied by animated(scene, time)
  // The graph file's parsed JSON, read when a track animates a node: each
  // frame's graph is built anew from it (scene/graph_animation.h).
  std::shared_ptr<const GraphDoc> graph_doc;
  // How the scene was read, for -v: "--set camera.fov replaces ..." for
  // each [[animation]] track a --set dropped (scene/overrides.h).
  std::vector<std::string> notes;
};

}  // namespace ms
