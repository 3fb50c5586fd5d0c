// What the mesh exporter hands its writers: a triangle mesh with a material
// id per vertex and normals per corner, or the narrow band of a level set.
// Plain data, no GL.
//
//   TriMesh m = ...;                          // mesh/dual_contour.h makes one
//   write_mesh(m, materials, "part.glb");     // the format from the extension
//   write_level_set(band, "part.vdb");        // an OpenVDB level set
//
// Every writer goes through io/atomic_file.h: the file appears complete or
// not at all, and a failed write throws Exit::system naming it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace ms {

// Counter-clockwise seen from outside: normals point out of the solid.
struct TriMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint16_t> material;  // per vertex: the scene's material index
  std::vector<std::uint32_t> indices;   // three per triangle
  // Unit normals, and for each corner (as `indices`) which of them: a
  // vertex on a crease has one per side. Both empty: no normals written.
  std::vector<glm::vec3> normals;
  std::vector<std::uint32_t> normal_index;
  std::size_t triangles() const { return indices.size() / 3; }
};

// The scene's materials, by index, for OBJ's .mtl and glTF's materials.
struct MeshMaterial {
  std::string name;
  glm::vec3 color{0.8f};  // linear RGB diffuse colour
};

// A narrow band of signed distances on a uniform grid, in world units:
// voxel (i, j, k) sits at origin + voxel * (i, j, k). Only the voxels with
// |value| < band are listed; the writer fills the rest (inside: -band,
// outside: +band, by flood fill from the band's signs).
struct LevelSetBand {
  std::string name;           // the grid's name in the file (the scene's name)
  double voxel = 0.0;         // world units per voxel
  glm::dvec3 origin{0.0};     // world position of voxel (0, 0, 0)
  float band = 0.0f;          // half-width, world units (3 voxels by default)
  std::vector<glm::ivec3> ijk;
  std::vector<float> value;   // signed distance, negative inside
};

enum class MeshFormat { obj, ply, stl, glb, vdb };
// By the extension, case-insensitive; nullopt for any other.
std::optional<MeshFormat> mesh_format_for(const std::filesystem::path& file);
const char* mesh_format_name(MeshFormat f);  // "obj", "ply", ...

// OBJ (text, with a .mtl beside it named after the file: `usemtl` groups by
// the first vertex's material; `vn` and `f v//vn`), PLY (binary
// little-endian, nx ny nz and a `material` vertex property), STL (binary,
// each facet's own normal), glTF 2.0 binary (.glb: NORMAL, a _MATERIAL
// vertex attribute and one primitive per material). PLY and GLB hold one
// normal per vertex, so a vertex with several is written once per normal.
// Throws bad_input for .vdb.
void write_mesh(const TriMesh& mesh, const std::vector<MeshMaterial>& materials,
                const std::filesystem::path& file);
// An OpenVDB FloatGrid of class level set, named, with its transform.
// Returns the written grid's active voxels (a voxel listed twice is one).
std::uint64_t write_level_set(const LevelSetBand& band, const std::filesystem::path& file);

}  // namespace ms
