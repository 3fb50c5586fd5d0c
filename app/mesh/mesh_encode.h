// What the mesh writers share (mesh_writers.cpp, glb_writer.cpp): the
// checks on a TriMesh, its vertices split where they have several normals,
// its triangles grouped by material, the materials' names, and a buffered
// writer over io/atomic_file.h. Internal to mesh/.
//
//   check_mesh(mesh, file);                     // bad_input naming the file
//   const MaterialGroups g = group_by_material(mesh);
//   for (const MaterialGroup& m : g.groups) ... g.order[m.first + t] ...
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "mesh/mesh.h"

namespace ms::mesh_detail {

// Indices a whole number of triangles, each within the positions, a
// material per vertex or none (all material 0), and a normal per corner,
// each within the normals, or none. Throws bad_input.
void check_mesh(const TriMesh& mesh, const std::filesystem::path& file);

// The vertices a format of one normal per vertex writes (PLY, GLB): vertex
// i is position i with its first corner's normal; a position with more
// normals is repeated after them all, once per other normal. Without
// normals, the positions as they are.
struct SplitVertices {
  std::vector<std::uint32_t> position;  // per vertex written: its position
  std::vector<std::uint32_t> normal;    // per vertex written: its normal (empty: no normals)
  std::vector<std::uint32_t> indices;   // the triangles, over the vertices written
};
SplitVertices split_by_normal(const TriMesh& mesh);

// A triangle's material: its first vertex's.
std::uint16_t triangle_material(const TriMesh& mesh, std::size_t t);

// Triangles `order[first, first + count)` have material `id`; groups by id,
// ascending, and only the ids some triangle has.
struct MaterialGroup {
  std::uint16_t id = 0;
  std::size_t first = 0, count = 0;
};
struct MaterialGroups {
  std::vector<std::uint32_t> order;  // triangle numbers, grouped
  std::vector<MaterialGroup> groups;
};
MaterialGroups group_by_material(const TriMesh& mesh);

// One name per group, unique, of [A-Za-z0-9_.-] only (OBJ's usemtl ends a
// name at the first space); "material_<id>" for an id without a material.
std::vector<std::string> group_names(const MaterialGroups& g, const std::vector<MeshMaterial>& materials);
glm::vec3 material_color(const std::vector<MeshMaterial>& materials, std::uint16_t id);

// Shortest text that reads back as the same float (std::to_chars).
void append_float(std::string& out, float v);

// Appends to a buffer and hands it to an AtomicFile a megabyte at a time,
// so a large mesh is never held twice in memory.
class BufferedFile {
 public:
  explicit BufferedFile(const std::filesystem::path& target) : file_(target) {}
  std::string& buffer() { return buf_; }  // append, then call flush_if_full()
  void put(const void* data, std::size_t n) { buf_.append(static_cast<const char*>(data), n); }
  void put_u8(std::uint8_t v) { buf_.push_back(static_cast<char>(v)); }
  void put_u16(std::uint16_t v);
  void put_u32(std::uint32_t v);
  void put_f32(float v);
  void flush_if_full() {
    if (buf_.size() >= (1u << 20)) flush();
  }
  void commit();  // the rest, then AtomicFile::commit()

 private:
  void flush();
  AtomicFile file_;
  std::string buf_;
};

// glb_writer.cpp
void write_glb(const TriMesh& mesh, const std::vector<MeshMaterial>& materials, const std::filesystem::path& file);

}  // namespace ms::mesh_detail
