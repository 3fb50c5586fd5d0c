// write_mesh(): OBJ (+ .mtl), binary PLY and binary STL here; GLB in
// glb_writer.cpp. Each file goes through io/atomic_file.h.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <set>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/version.h"
#include "mesh/mesh_encode.h"

namespace ms {
namespace fs = std::filesystem;
using namespace mesh_detail;

namespace mesh_detail {

namespace {

// Every index of `indices` (a "mesh index" or a "mesh normal index") names
// one of `count` elements (`of`), and a 32-bit index reaches them all.
void check_indices(const std::vector<std::uint32_t>& indices, std::size_t count, const std::string& what,
                   const std::string& of, const fs::path& file) {
  if (count > std::numeric_limits<std::uint32_t>::max())
    fail_input("mesh has more " + of + " than a 32-bit index reaches", file.string());
  for (std::uint32_t i : indices)
    if (i >= count)
      fail_input("mesh " + what + " " + std::to_string(i) + " is past its " + std::to_string(count) + " " + of,
                 file.string());
}

}  // namespace

void check_mesh(const TriMesh& mesh, const fs::path& file) {
  if (mesh.indices.size() % 3 != 0)
    fail_input("mesh indices are not whole triangles (" + std::to_string(mesh.indices.size()) + ")", file.string());
  if (!mesh.material.empty() && mesh.material.size() != mesh.positions.size())
    fail_input("mesh has " + std::to_string(mesh.material.size()) + " material ids for " +
                   std::to_string(mesh.positions.size()) + " vertices",
               file.string());
  check_indices(mesh.indices, mesh.positions.size(), "index", "vertices", file);
  if (mesh.normals.empty() && mesh.normal_index.empty()) return;
  if (mesh.normal_index.size() != mesh.indices.size())
    fail_input("mesh has " + std::to_string(mesh.normal_index.size()) + " normal indices for " +
                   std::to_string(mesh.indices.size()) + " corners",
               file.string());
  check_indices(mesh.normal_index, mesh.normals.size(), "normal index", "normals", file);
}

SplitVertices split_by_normal(const TriMesh& mesh) {
  SplitVertices s;
  s.position.resize(mesh.positions.size());
  std::iota(s.position.begin(), s.position.end(), 0u);
  s.indices = mesh.indices;
  if (mesh.normal_index.empty()) return s;
  constexpr std::uint32_t kNone = 0xffffffffu;
  s.normal.assign(mesh.positions.size(), kNone);
  for (std::size_t c = 0; c < mesh.indices.size(); ++c)
    if (s.normal[mesh.indices[c]] == kNone) s.normal[mesh.indices[c]] = mesh.normal_index[c];
  // A position no triangle uses still needs a normal to write: any.
  for (std::uint32_t& n : s.normal)
    if (n == kNone) n = 0;
  std::unordered_map<std::uint64_t, std::uint32_t> extra;  // position << 32 | normal -> vertex
  for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
    const std::uint32_t p = mesh.indices[c], n = mesh.normal_index[c];
    if (s.normal[p] == n) continue;
    const auto [it, added] = extra.try_emplace(std::uint64_t{p} << 32 | n, static_cast<std::uint32_t>(s.position.size()));
    if (added) {
      s.position.push_back(p);
      s.normal.push_back(n);
    }
    s.indices[c] = it->second;
  }
  return s;
}

std::uint16_t triangle_material(const TriMesh& mesh, std::size_t t) {
  return mesh.material.empty() ? 0 : mesh.material[mesh.indices[3 * t]];
}

MaterialGroups group_by_material(const TriMesh& mesh) {
  MaterialGroups g;
  g.order.resize(mesh.triangles());
  for (std::size_t t = 0; t < g.order.size(); ++t) g.order[t] = static_cast<std::uint32_t>(t);
  // Stable: within a material the triangles keep the mesher's order.
  std::stable_sort(g.order.begin(), g.order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return triangle_material(mesh, a) < triangle_material(mesh, b);
  });
  for (std::size_t i = 0; i < g.order.size(); ++i) {
    const std::uint16_t id = triangle_material(mesh, g.order[i]);
    if (g.groups.empty() || g.groups.back().id != id) g.groups.push_back({id, i, 0});
    ++g.groups.back().count;
  }
  return g;
}

std::vector<std::string> group_names(const MaterialGroups& g, const std::vector<MeshMaterial>& materials) {
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (const MaterialGroup& m : g.groups) {
    std::string name = m.id < materials.size() ? materials[m.id].name : std::string();
    for (char& c : name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
    if (name.empty()) name = "material_" + std::to_string(m.id);
    if (taken.count(name)) name += "_" + std::to_string(m.id);
    taken.insert(name);
    names.push_back(name);
  }
  return names;
}

glm::vec3 material_color(const std::vector<MeshMaterial>& materials, std::uint16_t id) {
  return id < materials.size() ? materials[id].color : MeshMaterial{}.color;
}

void append_float(std::string& out, float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void BufferedFile::put_u16(std::uint16_t v) {
  const char b[2] = {char(v & 0xff), char(v >> 8)};
  buf_.append(b, 2);
}

void BufferedFile::put_u32(std::uint32_t v) {
  const char b[4] = {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff), char(v >> 24)};
  buf_.append(b, 4);
}

void BufferedFile::put_f32(float v) {
  std::uint32_t u;
  std::memcpy(&u, &v, 4);
  put_u32(u);
}

void BufferedFile::flush() {
  file_.write(buf_.data(), buf_.size());  // a failure is kept for commit()
  buf_.clear();
}

void BufferedFile::commit() {
  flush();
  file_.commit();
}

}  // namespace mesh_detail

namespace {

void append_vec3(std::string& out, const char* tag, const glm::vec3& v) {
  out += tag;
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_float(out, v[i]);
  }
  out += '\n';
}

void write_mtl(const MaterialGroups& g, const std::vector<std::string>& names,
               const std::vector<MeshMaterial>& materials, const fs::path& file) {
  std::string text = std::string("# marchstudio ") + kVersion + "\n";
  for (std::size_t i = 0; i < g.groups.size(); ++i) {
    text += "\nnewmtl " + names[i] + "\n";
    append_vec3(text, "Kd", material_color(materials, g.groups[i].id));
    text += "Ka 0 0 0\nKs 0 0 0\nillum 1\n";
  }
  write_file_atomic(file, text);
}

void write_obj_text(const TriMesh& mesh, const MaterialGroups& g, const std::vector<std::string>& names,
                    const fs::path& mtl, const fs::path& file) {
  BufferedFile out(file);
  std::string& b = out.buffer();
  b = std::string("# marchstudio ") + kVersion + "\nmtllib " + mtl.filename().string() + "\n";
  for (const glm::vec3& p : mesh.positions) {
    append_vec3(b, "v", p);
    out.flush_if_full();
  }
  for (const glm::vec3& n : mesh.normals) {
    append_vec3(b, "vn", n);
    out.flush_if_full();
  }
  const bool normals = !mesh.normal_index.empty();
  char num[16];
  const auto append_index = [&](std::uint32_t i) {
    b.append(num, std::to_chars(num, num + sizeof num, std::uint64_t(i) + 1).ptr);  // 1-based
  };
  for (std::size_t i = 0; i < g.groups.size(); ++i) {
    b += "usemtl " + names[i] + "\n";
    for (std::size_t k = 0; k < g.groups[i].count; ++k) {
      const std::uint32_t t = g.order[g.groups[i].first + k];
      b += 'f';
      for (int c = 0; c < 3; ++c) {
        b += ' ';
        append_index(mesh.indices[3 * t + c]);
        if (!normals) continue;
        b += "//";
        append_index(mesh.normal_index[3 * t + c]);
      }
      b += '\n';
      out.flush_if_full();
    }
  }
  out.commit();
}

// The .mtl first, so the .obj never names a file that is not there; if the
// .obj then fails, the .mtl it would have named goes too.
void write_obj(const TriMesh& mesh, const std::vector<MeshMaterial>& materials, const fs::path& file) {
  const MaterialGroups g = group_by_material(mesh);
  const std::vector<std::string> names = group_names(g, materials);
  fs::path mtl = file;
  mtl.replace_extension(".mtl");
  write_mtl(g, names, materials, mtl);
  try {
    write_obj_text(mesh, g, names, mtl, file);
  } catch (...) {
    std::error_code ec;
    if (output_kind(mtl) == OutputKind::replace) fs::remove(mtl, ec);
    throw;
  }
}

void write_ply(const TriMesh& mesh, const fs::path& file) {
  const SplitVertices sv = split_by_normal(mesh);
  const bool normals = !sv.normal.empty();
  BufferedFile out(file);
  out.buffer() = std::string("ply\nformat binary_little_endian 1.0\ncomment marchstudio ") + kVersion +
                 "\nelement vertex " + std::to_string(sv.position.size()) +
                 "\nproperty float x\nproperty float y\nproperty float z\n" +
                 (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "") +
                 "property ushort material\nelement face " + std::to_string(mesh.triangles()) +
                 "\nproperty list uchar uint vertex_indices\nend_header\n";
  for (std::size_t v = 0; v < sv.position.size(); ++v) {
    const std::uint32_t p = sv.position[v];
    for (int c = 0; c < 3; ++c) out.put_f32(mesh.positions[p][c]);
    if (normals)
      for (int c = 0; c < 3; ++c) out.put_f32(mesh.normals[sv.normal[v]][c]);
    out.put_u16(mesh.material.empty() ? 0 : mesh.material[p]);
    out.flush_if_full();
  }
  for (std::size_t t = 0; t < mesh.triangles(); ++t) {
    out.put_u8(3);
    for (int c = 0; c < 3; ++c) out.put_u32(sv.indices[3 * t + c]);
    out.flush_if_full();
  }
  out.commit();
}

// Counter-clockwise seen from outside, so the right-hand normal points out.
glm::vec3 facet_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float len = glm::length(n);
  return len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f);
}

void write_stl(const TriMesh& mesh, const fs::path& file) {
  if (mesh.triangles() > std::numeric_limits<std::uint32_t>::max())
    fail_input("binary STL holds at most 2^32-1 triangles", file.string());
  BufferedFile out(file);
  // Not "solid": readers take a header that starts so for ASCII STL.
  std::string header = std::string("marchstudio ") + kVersion + " binary STL";
  header.resize(80, '\0');
  out.buffer() = header;
  out.put_u32(static_cast<std::uint32_t>(mesh.triangles()));
  for (std::size_t t = 0; t < mesh.triangles(); ++t) {
    const glm::vec3 v[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                            mesh.positions[mesh.indices[3 * t + 2]]};
    const glm::vec3 n = facet_normal(v[0], v[1], v[2]);
    for (int c = 0; c < 3; ++c) out.put_f32(n[c]);
    for (const glm::vec3& p : v)
      for (int c = 0; c < 3; ++c) out.put_f32(p[c]);
    out.put_u16(0);
    out.flush_if_full();
  }
  out.commit();
}

}  // namespace

void write_mesh(const TriMesh& mesh, const std::vector<MeshMaterial>& materials, const fs::path& file) {
  const std::optional<MeshFormat> format = mesh_format_for(file);
  if (!format) fail_input("not a mesh file name (.obj, .ply, .stl, .glb)", file.string());
  if (*format == MeshFormat::vdb)
    fail_input("a .vdb holds a level set, not a mesh", file.string(), 0, {}, "write_level_set() writes it");
  check_mesh(mesh, file);
  switch (*format) {
    case MeshFormat::obj: write_obj(mesh, materials, file); break;
    case MeshFormat::ply: write_ply(mesh, file); break;
    case MeshFormat::stl: write_stl(mesh, file); break;
    case MeshFormat::glb: write_glb(mesh, materials, file); break;
    case MeshFormat::vdb: break;
  }
}

}  // namespace ms
