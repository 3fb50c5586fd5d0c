// .glb: glTF 2.0's binary container, assembled here with nlohmann::json
// rather than tinygltf's writer. The executable then loads no glTF library
// (start-up, and tools/gpu's lean bench, which links pipeline/ and so
// mesh/, carries none); the tests read what this writes with tinygltf's
// loader. One mesh, one primitive per material group, all sharing the
// POSITION, NORMAL and _MATERIAL accessors (a vertex with several normals
// written once per normal: glTF has one per vertex, and unit length).
//
// _MATERIAL is FLOAT SCALAR, not UNSIGNED_SHORT: glTF allows any type on
// an application-specific ("_") attribute, but importers (Blender's among
// them) read custom attributes most reliably as floats, and a float holds
// every 16-bit id exactly.
#include <limits>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"

#include "core/version.h"
#include "mesh/mesh_encode.h"

namespace ms::mesh_detail {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kFloat = 5126, kUint = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

json position_accessor(const TriMesh& mesh) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {{"bufferView", 0}, {"componentType", kFloat}, {"type", "VEC3"}, {"min", {lo.x, lo.y, lo.z}},
          {"max", {hi.x, hi.y, hi.z}}};
}

// The JSON chunk, and the BIN chunk's size: positions, normals, material
// ids, indices, each of the vertices `sv` writes.
json gltf_document(const TriMesh& mesh, const SplitVertices& sv, const std::vector<MeshMaterial>& materials,
                   const MaterialGroups& g, std::size_t& bin_size) {
  const std::size_t nv = sv.position.size(), ni = mesh.indices.size();
  const std::size_t pos_bytes = 12 * nv, nrm_bytes = sv.normal.empty() ? 0 : 12 * nv, mat_bytes = 4 * nv,
                    idx_bytes = 4 * ni;
  bin_size = pos_bytes + nrm_bytes + mat_bytes + idx_bytes;
  json doc = {{"asset", {{"version", "2.0"}, {"generator", std::string("marchstudio ") + kVersion}}},
              {"scene", 0}};
  if (ni == 0) {  // an accessor may not be empty: no mesh at all
    doc["scenes"] = json::array({json::object({{"nodes", json::array()}})});
    bin_size = 0;
    return doc;
  }
  doc["scenes"] = json::array({{{"nodes", {0}}}});
  doc["nodes"] = json::array({{{"mesh", 0}}});
  doc["buffers"] = json::array({{{"byteLength", bin_size}}});
  json views = json::array(), accessors = json::array(), attributes = json::object();
  std::size_t offset = 0;
  // One view per attribute, in the BIN chunk's order, and its accessor.
  const auto attribute = [&](const char* name, std::size_t bytes, json accessor) {
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", kArrayBuffer}};
    if (accessor["type"] == "VEC3") view["byteStride"] = 12;
    accessor["bufferView"] = views.size();
    accessor["count"] = nv;
    attributes[name] = accessors.size();
    views.push_back(std::move(view));
    accessors.push_back(std::move(accessor));
    offset += bytes;
  };
  attribute("POSITION", pos_bytes, position_accessor(mesh));
  if (nrm_bytes) attribute("NORMAL", nrm_bytes, {{"componentType", kFloat}, {"type", "VEC3"}});
  attribute("_MATERIAL", mat_bytes, {{"componentType", kFloat}, {"type", "SCALAR"}});
  const std::size_t index_view = views.size();
  views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", idx_bytes}, {"target", kElementArrayBuffer}});
  json primitives = json::array(), mats = json::array();
  const std::vector<std::string> names = group_names(g, materials);
  for (std::size_t i = 0; i < g.groups.size(); ++i) {
    const glm::vec3 c = material_color(materials, g.groups[i].id);
    mats.push_back({{"name", names[i]},
                    {"pbrMetallicRoughness",
                     {{"baseColorFactor", {c.r, c.g, c.b, 1.0f}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
                    {"extras", {{"marchstudio_material", g.groups[i].id}}}});
    accessors.push_back({{"bufferView", index_view}, {"byteOffset", 12 * g.groups[i].first}, {"componentType", kUint},
                         {"count", 3 * g.groups[i].count}, {"type", "SCALAR"}});
    primitives.push_back({{"attributes", attributes}, {"indices", accessors.size() - 1}, {"material", i},
                          {"mode", kTriangles}});
  }
  doc["bufferViews"] = std::move(views);
  doc["accessors"] = std::move(accessors);
  doc["materials"] = std::move(mats);
  doc["meshes"] = json::array({{{"primitives", std::move(primitives)}}});
  return doc;
}

}  // namespace

void write_glb(const TriMesh& mesh, const std::vector<MeshMaterial>& materials, const fs::path& file) {
  const MaterialGroups g = group_by_material(mesh);
  const SplitVertices sv = split_by_normal(mesh);
  BufferedFile out(file);
  std::size_t bin_size = 0;
  std::string text = gltf_document(mesh, sv, materials, g, bin_size).dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned; JSON pads with spaces
  const std::uint64_t total = 12 + 8 + text.size() + (bin_size ? 8 + bin_size : 0);
  if (total > std::numeric_limits<std::uint32_t>::max())
    fail_input("mesh too large for a .glb (4 GiB at most)", file.string(), 0, {}, "write .ply or .obj");
  out.put("glTF", 4);
  out.put_u32(2);
  out.put_u32(static_cast<std::uint32_t>(total));
  out.put_u32(static_cast<std::uint32_t>(text.size()));
  out.put("JSON", 4);
  out.buffer() += text;
  if (bin_size) {
    out.put_u32(static_cast<std::uint32_t>(bin_size));  // every part a multiple of 4: no padding
    out.put("BIN\0", 4);
    for (std::uint32_t p : sv.position) {
      for (int c = 0; c < 3; ++c) out.put_f32(mesh.positions[p][c]);
      out.flush_if_full();
    }
    for (std::uint32_t n : sv.normal) {
      for (int c = 0; c < 3; ++c) out.put_f32(mesh.normals[n][c]);
      out.flush_if_full();
    }
    for (std::uint32_t p : sv.position) {
      out.put_f32(mesh.material.empty() ? 0.0f : static_cast<float>(mesh.material[p]));
      out.flush_if_full();
    }
    for (std::uint32_t t : g.order) {
      for (int c = 0; c < 3; ++c) out.put_u32(sv.indices[3 * t + c]);
      out.flush_if_full();
    }
  }
  out.commit();
}

}  // namespace ms::mesh_detail
