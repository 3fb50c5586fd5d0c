// Meshes as `marchstudio mesh` writes them, read back by hand for the
// tests (GLB is read with tinygltf, in the unit tests alone): OBJ's v, vn
// and `f v//vn` lines, binary PLY's x y z, optional nx ny nz, and material.
//
//   const ReadMesh m = read_ply(dir / "out.ply");
//   m.normals[m.normal_index[c]]   // corner c's normal
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace ms::test {

struct ReadMesh {
  std::vector<glm::vec3> positions;           // the file's vertices (OBJ: its v lines)
  std::vector<glm::vec3> normals;             // OBJ: its vn lines; PLY: one per vertex; empty: none
  std::vector<std::uint16_t> material;        // PLY: one per vertex
  std::vector<std::uint32_t> indices;         // three per triangle, 0-based
  std::vector<std::uint32_t> normal_index;    // per corner, when there are normals
  bool ok = false;                            // the whole file was read
};

inline ReadMesh read_obj(const std::filesystem::path& file) {
  std::ifstream in(file);
  ReadMesh m;
  std::string line;
  const auto vec = [](std::istringstream& s) {
    glm::vec3 v;
    s >> v.x >> v.y >> v.z;
    return v;
  };
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") m.positions.push_back(vec(s));
    else if (tag == "vn") m.normals.push_back(vec(s));
    else if (tag == "f")
      for (int c = 0; c < 3; ++c) {
        std::string corner;
        s >> corner;
        const std::size_t slash = corner.find("//");
        m.indices.push_back(static_cast<std::uint32_t>(std::stoul(corner) - 1));
        if (slash != std::string::npos)
          m.normal_index.push_back(static_cast<std::uint32_t>(std::stoul(corner.substr(slash + 2)) - 1));
      }
  }
  m.ok = in.eof();
  return m;
}

inline ReadMesh read_ply(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  ReadMesh m;
  std::string line;
  std::size_t nv = 0, nf = 0;
  bool normals = false;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream s(line);
    std::string a, b, c;
    s >> a >> b >> c;
    if (a == "element" && b == "vertex") nv = std::stoul(c);
    if (a == "element" && b == "face") nf = std::stoul(c);
    if (a == "property" && c == "nx") normals = true;
  }
  const auto get = [&in](auto& v) { in.read(reinterpret_cast<char*>(&v), sizeof v); };
  for (std::size_t i = 0; i < nv; ++i) {
    glm::vec3 p, n;
    std::uint16_t mat = 0;
    get(p);
    if (normals) get(n), m.normals.push_back(n);
    get(mat);
    m.positions.push_back(p);
    m.material.push_back(mat);
  }
  for (std::size_t i = 0; i < nf; ++i) {
    std::uint8_t count = 0;
    std::uint32_t t[3];
    get(count);
    get(t);
    m.indices.insert(m.indices.end(), t, t + 3);
  }
  if (normals) m.normal_index = m.indices;
  m.ok = in.good() && in.peek() == EOF;
  return m;
}

// The file's vertices that differ in position (a vertex written once per
// normal counts once): the mesh's own vertices.
inline std::size_t distinct_positions(const ReadMesh& m) {
  std::set<std::tuple<float, float, float>> seen;
  for (const glm::vec3& p : m.positions) seen.emplace(p.x, p.y, p.z);
  return seen.size();
}

// The angle between two directions, in degrees.
inline double degrees(const glm::vec3& a, const glm::vec3& b) {
  const double c = glm::dot(glm::normalize(a), glm::normalize(b));
  return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

// Per position in the file, its distinct normals (a crease vertex has one
// per side).
inline std::map<std::tuple<float, float, float>, std::set<std::tuple<float, float, float>>> normals_at(
    const ReadMesh& r) {
  std::map<std::tuple<float, float, float>, std::set<std::tuple<float, float, float>>> out;
  for (std::size_t c = 0; c < r.indices.size(); ++c) {
    const glm::vec3 p = r.positions[r.indices[c]], n = r.normals[r.normal_index[c]];
    out[{p.x, p.y, p.z}].emplace(n.x, n.y, n.z);
  }
  return out;
}

}  // namespace ms::test
