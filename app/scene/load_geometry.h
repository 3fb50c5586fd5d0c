// [[planes]] and [bounds]: the analytic geometry a scene declares besides
// map() (docs/scene-format.md). The scene loader (load.cpp) calls these;
// the field lists are here so its schema can list their keys.
#pragma once
#include <functional>
#include <string>
#include <string_view>

#include "scene/scene.h"
#include "scene/toml_read.h"

namespace ms {

inline const Field<Plane> kPlaneFields[] = {
    {"normal", &Plane::normal},
    {"offset", &Plane::offset},
};
inline const Field<Bounds> kBoundsFields[] = {
    {"center", &Bounds::center},
    {"radius", &Bounds::radius, Range::above(0)},
    {"min", &Bounds::min},
    {"max", &Bounds::max},
};

// Checks a table's keys against the schema of `section`, naming `path`.
using CheckKeys = std::function<void(const toml::table&, std::string_view section, const std::string& path)>;

// [[planes]], read after the materials they name: at most 8, each normal
// non-zero (stored normalised), each material an existing name.
void read_planes(const Reader& r, const CheckKeys& check, const toml::table& root, Scene& scene);

// [bounds]: a sphere (center, radius) or a box (min, max), never both and
// never half of one; a box's max above its min in every component.
void read_bounds(const Reader& r, const CheckKeys& check, const toml::table& root, Bounds& b);

}  // namespace ms
