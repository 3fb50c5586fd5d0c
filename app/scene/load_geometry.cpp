#include "scene/load_geometry.h"

#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>

#include "core/suggest.h"

namespace ms {
namespace {

constexpr std::size_t kMaxPlanes = 8;
constexpr double kTinySq = 1e-12;  // squared length below which a normal has no direction

double length_sq(const glm::vec3& v) { return glm::dot(glm::dvec3(v), glm::dvec3(v)); }

}  // namespace

void read_planes(const Reader& r, const CheckKeys& check, const toml::table& root, Scene& scene) {
  const auto tables = r.tables(root, {}, "planes");
  if (tables.size() > kMaxPlanes)
    r.fail(Reader::line_of(*tables[kMaxPlanes]), "planes",
           "too many planes: " + std::to_string(tables.size()) + " (at most " + std::to_string(kMaxPlanes) + ")");
  std::vector<std::string_view> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string path = "planes[" + std::to_string(i) + "]";
    Plane plane;
    check(t, "planes", path);
    r.read_fields(t, path, kPlaneFields, plane);
    if (length_sq(plane.normal) <= kTinySq)
      r.fail(Reader::line_of(t, "normal"), path + ".normal", quote(path + ".normal") + " must not be zero-length");
    plane.normal = glm::normalize(plane.normal);
    const std::string key = path + ".material";
    if (!r.read(t, path, "material", plane.material))
      r.fail(Reader::line_of(t), key, "missing required key " + quote(key),
             "name the plane's [[materials]] entry, e.g. material = \"floor\"");
    const auto it = std::find(names.begin(), names.end(), plane.material);
    if (it == names.end()) {
      const std::string hint = did_you_mean(plane.material, names);
      r.fail(Reader::line_of(t, "material"), key, "unknown material " + quote(plane.material) + " for " + quote(key),
             hint.empty() ? "it must be the name of a [[materials]] entry" : hint);
    }
    plane.material_id = static_cast<int>(it - names.begin());
    scene.planes.push_back(std::move(plane));
  }
}

void read_bounds(const Reader& r, const CheckKeys& check, const toml::table& root, Bounds& b) {
  const toml::table* t = r.table(root, {}, "bounds");
  if (!t) return;
  check(*t, "bounds", "bounds");
  r.read_fields(*t, "bounds", kBoundsFields, b);
  const bool sphere = t->contains("center") || t->contains("radius");
  const bool box = t->contains("min") || t->contains("max");
  const auto need = [&](std::string_view have, std::string_view missing) {
    if (!t->contains(missing))
      r.fail(Reader::line_of(*t, have), "bounds." + std::string(missing),
             "'bounds." + std::string(have) + "' needs 'bounds." + std::string(missing) + "'",
             "a bounding sphere is center and radius; a box is min and max");
  };
  if (sphere && box)
    r.fail(Reader::line_of(*t, t->contains("min") ? "min" : "max"), "bounds",
           "[bounds] is either a sphere (center, radius) or a box (min, max), not both");
  if (sphere) {
    need(t->contains("center") ? "center" : "radius", "center");
    need("center", "radius");
    b.kind = BoundsKind::sphere;
  } else if (box) {
    need(t->contains("min") ? "min" : "max", "min");
    need("min", "max");
    for (int c = 0; c < 3; ++c)
      if (!(b.min[c] < b.max[c]))
        r.fail(Reader::line_of(*t, "max"), "bounds.max",
               "'bounds.max' must be greater than 'bounds.min' in every component, got " + format_number(b.max[c]) +
                   " <= " + format_number(b.min[c]),
               "min is the box's lowest corner, max its highest");
    b.kind = BoundsKind::box;
  } else {
    r.fail(Reader::line_of(*t), "bounds", "[bounds] is empty",
           "give center and radius (a sphere) or min and max (a box), or remove it");
  }
}

}  // namespace ms
