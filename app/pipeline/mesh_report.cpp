#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/format.h"
#include "pipeline/mesh_job.h"

namespace ms {

std::string mesh_report_json(const MeshReport& r) {
  nlohmann::ordered_json j;
  j["schema"] = "marchstudio.mesh/1";
  j["output"] = r.output;
  j["written"] = r.written;
  j["format"] = mesh_format_name(r.format);
  j["cells"] = {r.cells.x, r.cells.y, r.cells.z};
  j["voxel"] = r.voxel;
  j["bricks"] = r.bricks;
  j["samples"] = r.samples;
  j["readback_bytes"] = r.readback_bytes;
  j["nonfinite_samples"] = r.nonfinite;
  if (r.format == MeshFormat::vdb) {
    j["band_voxels"] = r.band_voxels;
  } else {
    j["vertices"] = r.vertices;
    j["triangles"] = r.triangles;
    j["surface_cells"] = r.surface_cells;
    j["split_cells"] = r.split_cells;
    j["untangled_vertices"] = r.untangled;
    j["max_vertex_error_voxels"] = r.accuracy.max_vertex;
    j["mean_vertex_error_voxels"] = r.accuracy.mean_vertex;
    j["hausdorff_voxels"] = r.accuracy.hausdorff;
    j["mesh_to_surface_voxels"] = r.accuracy.mesh_to_surface;
    j["surface_to_mesh_voxels"] = r.accuracy.surface_to_mesh;
    j["manifold"] = r.check.ok();
    j["check"] = {{"summary", r.check.summary()},
                  {"boundary_edges", r.check.boundary_edges},
                  {"nonmanifold_edges", r.check.nonmanifold_edges},
                  {"flipped_edges", r.check.flipped_edges},
                  {"nonmanifold_vertices", r.check.nonmanifold_vertices},
                  {"self_intersections", r.check.self_intersections},
                  {"euler", r.check.euler},
                  {"volume", r.check.volume}};
  }
  j["stages"] = {{"setup_s", r.setup_s}, {"sample_s", r.sample_s}, {"mesh_s", r.mesh_s}, {"check_s", r.check_s}, {"write_s", r.write_s}};
  j["seconds"] = r.seconds;
  return j.dump();
}

std::string mesh_summary(const MeshReport& r) {
  char buf[256];
  if (r.format == MeshFormat::vdb)
    std::snprintf(buf, sizeof buf, "%s: level set, %zu active voxels, %.2f s", r.output.c_str(), r.band_voxels,
                  r.seconds);
  else
    std::snprintf(buf, sizeof buf, "%s: %zu triangles, %zu vertices, %s, %.2f s", r.output.c_str(), r.triangles,
                  r.vertices, r.check.ok() ? "watertight" : "NOT watertight", r.seconds);
  return buf;
}

std::vector<std::string> mesh_report_lines(const MeshReport& r) {
  std::vector<std::string> out;
  char buf[320];
  std::snprintf(buf, sizeof buf, "grid %dx%dx%d cells of %.6g, %zu bricks sampled, %zu map() calls, %.1f MB read back",
                r.cells.x, r.cells.y, r.cells.z, r.voxel, r.bricks, r.samples, r.readback_bytes / 1e6);
  out.push_back(buf);
  if (r.format != MeshFormat::vdb) {
    std::snprintf(buf, sizeof buf, "vertices |map| max %.4f, mean %.4f voxel; Hausdorff (estimated) %.4f voxel (mesh to surface %.4f, surface to mesh %.4f)",
                  r.accuracy.max_vertex, r.accuracy.mean_vertex, r.accuracy.hausdorff, r.accuracy.mesh_to_surface,
                  r.accuracy.surface_to_mesh);
    out.push_back(buf);
    std::snprintf(buf, sizeof buf, "check: %s; Euler characteristic %lld; %zu cells, %zu with split vertices, %zu vertices moved to untangle",
                  r.check.summary().c_str(), r.check.euler, r.surface_cells, r.split_cells, r.untangled);
    out.push_back(buf);
  }
  std::snprintf(buf, sizeof buf, "time: setup %.3f s, sampling %.3f s, meshing %.3f s, check %.3f s, writing %.3f s",
                r.setup_s, r.sample_s - r.setup_s, r.mesh_s, r.check_s, r.write_s);
  out.push_back(buf);
  return out;
}

}  // namespace ms
