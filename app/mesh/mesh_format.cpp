#include <algorithm>
#include <cctype>

#include "mesh/mesh.h"

namespace ms {

std::optional<MeshFormat> mesh_format_for(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".stl") return MeshFormat::stl;
  if (ext == ".glb") return MeshFormat::glb;
  if (ext == ".vdb") return MeshFormat::vdb;
  return std::nullopt;
}

const char* mesh_format_name(MeshFormat f) {
  switch (f) {
    case MeshFormat::obj: return "obj";
    case MeshFormat::ply: return "ply";
    case MeshFormat::stl: return "stl";
    case MeshFormat::glb: return "glb";
    case MeshFormat::vdb: return "vdb";
  }
  return "?";
}

}  // namespace ms
