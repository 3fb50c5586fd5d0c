#include "pipeline/mesh_job.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/clock.h"
#include "core/error.h"
#include "core/format.h"
#include "core/memory_budget.h"
#include "io/atomic_file.h"
#include "io/temp_cleanup.h"
#include "mesh/dual_contour.h"
#include "mesh/sparse_field.h"
#include "mesh/untangle.h"
#include "mesh/vertex_normals.h"
#include "pipeline/guarded_job.h"
#include "pipeline/input.h"
#include "pipeline/nonfinite.h"
#include "render/field_sampler.h"
#include "render/graph_field.h"
#include "render/program.h"
#include "render/uniforms.h"
#include "scene/animation.h"
#include "scene/graph_animation.h"
#include "scene/graph_alone.h"

namespace ms {

namespace fs = std::filesystem;

namespace {

// The box the export covers and the cut that closes every surface there:
// --bounds, else the scene's [bounds] (a sphere cuts as a sphere).
FieldClip clip_for(const MeshJob& job, const Scene& scene, MeshBox& box) {
  FieldClip c;
  c.planes = job.planes;
  if (job.bounds) {
    box = *job.bounds;
  } else if (scene.bounds.kind == BoundsKind::sphere) {
    box = {scene.bounds.center - scene.bounds.radius, scene.bounds.center + scene.bounds.radius};
    c.sphere = true;
    c.a = glm::vec4(scene.bounds.center, scene.bounds.radius);
    return c;
  } else if (scene.bounds.kind == BoundsKind::box) {
    box = {scene.bounds.min, scene.bounds.max};
  } else {
    fail_input("the scene declares no [bounds]: mesh needs a box to cover", scene.file.string(), 0, "bounds",
               "add [bounds] to the scene, or give --bounds x0,y0,z0,x1,y1,z1");
  }
  c.a = glm::vec4(box.min, 0.0f);
  c.b = glm::vec4(box.max, 0.0f);
  return c;
}

std::vector<MeshMaterial> materials_of(const Scene& scene) {
  std::vector<MeshMaterial> out;
  for (const Material& m : scene.materials) out.push_back({m.name, m.color});
  return out;
}

// A --voxel finer than the cell limit allows on this box: refused before
// the grid is sized (its cell count would overflow an int).
void check_voxel(const MeshJob& job, const MeshBox& box) {
  if (job.voxel <= 0.0) return;
  const glm::dvec3 size = glm::dvec3(box.max) - glm::dvec3(box.min);
  const double longest = std::max({size.x, size.y, size.z}), cells = longest / job.voxel;
  if (cells <= kMaxMeshCells) return;
  fail_input("--voxel " + format_number(job.voxel) + " makes " + format_number(cells) +
                 " cells along the box's longest side, over the limit of " + std::to_string(kMaxMeshCells),
             {}, 0, "--voxel", "give --voxel " + format_number(longest / kMaxMeshCells) + " or more");
}

// Before bricks are sampled: what the export would hold for `bricks`
// against the memory budget, with a grid that fits (the bricks grow as the
// surface's area, the square of the cells along a side).
void check_memory(double bricks, const MeshJob& job) {
  const double need = bricks * kBytesPerBrick, budget = memory_budget();
  if (need <= budget) return;
  const double shrink = 0.9 * std::sqrt(budget / need);
  const std::string hint =
      job.voxel > 0.0 ? "give --voxel " + format_number(job.voxel / shrink) + " or more"
                      : "give --resolution " + std::to_string(std::max(8, static_cast<int>(job.resolution * shrink))) +
                            " or less, or a smaller --bounds";
  throw Error({Exit::system, job.frame.input.string(), 0, job.voxel > 0.0 ? "--voxel" : "--resolution",
               "the mesh needs about " + format_bytes(need) + ", over the " + format_bytes(budget) + " memory budget",
               hint, {}});
}

// Every sampled voxel within the band, from the bricks as sampled (a voxel
// two bricks share is listed twice, with one value; NaN and Inf left out).
LevelSetBand band_of(const SparseField& f, const Scene& scene, int band) {
  LevelSetBand b;
  b.name = scene.name.empty() ? "surface" : scene.name;
  b.voxel = f.grid.voxel;
  b.origin = f.grid.origin;
  b.band = static_cast<float>(band * f.grid.voxel);
  for (std::size_t s = 0; s < f.bricks.size(); ++s)
    for (int i = 0; i < kBrickCorners; ++i) {
      const float v = f.brick_values(s)[i];
      if (!(std::abs(v) < b.band)) continue;
      b.ijk.push_back(f.bricks[s] * kBrick + SparseField::corner_at(i));
      b.value.push_back(v);
    }
  return b;
}

// The sparse field meshed, checked and measured, into r.
TriMesh mesh_of(FieldSampler& sampler, const SparseField& sparse, const Scene& scene, const MeshJob& job,
                const MeshProgress& progress, MeshReport& r) {
  const auto m = Clock::now();
  DualContour dc = dual_contour(sampler, sparse, progress);
  if (dc.mesh.positions.empty() && sparse.nonfinite > 0)
    fail_input("no surface inside the box: map() is NaN or Inf at " + std::to_string(sparse.nonfinite) + " of " +
                   std::to_string(sparse.samples) + " samples and positive (or negative) elsewhere",
               scene.file.string(), 0, "map", "see docs/stability.md");
  if (dc.mesh.positions.empty())
    fail_input("no surface inside the box: map() is positive (or negative) everywhere there", scene.file.string(),
               0, job.bounds ? "--bounds" : "bounds");
  const std::size_t crossings = untangle(dc, sparse.grid);
  vertex_normals(sampler, dc);
  r.accuracy = measure_accuracy(sampler, dc, sparse.grid.voxel);
  r.mesh_s = seconds_since(m);
  if (progress) progress("checking", 0.8);
  const auto c = Clock::now();
  r.check = check_mesh(dc.mesh, sparse.grid.voxel, &crossings);
  r.check_s = seconds_since(c);
  r.vertices = dc.mesh.positions.size();
  r.triangles = dc.mesh.triangles();
  r.surface_cells = dc.cells;
  r.split_cells = dc.split_cells;
  r.untangled = dc.untangled;
  return std::move(dc.mesh);
}

// Everything that can fail on bad input, before any GL: the format, the
// output path, the scene (one with a field), its box.
const LoadedInput& checked_input(const MeshJob& job, LoadedInput& in, MeshReport& r) {
  r.output = job.output.string();
  const bool no_file = job.output.empty() && job.mesh_out;
  const std::optional<MeshFormat> format = no_file ? MeshFormat::obj : mesh_format_for(job.output);
  if (!format)
    fail_input("cannot tell the mesh format of '" + job.output.string() + "'", {}, 0, "-o",
               "name the output .obj, .ply, .stl, .glb or .vdb");
  r.format = *format;
  if (!no_file) output_kind(job.output, "-o");
  in = load_input_scene(job.frame.input, job.frame.disable, job.frame.assemble_options(), job.frame.preset,
                        job.frame.set);
  if (job.frame.verbose) report_scene_notes(in.scene, job.frame.input.string());
  if (in.shadertoy)
    fail_input("a Shadertoy shader has no map(): there is no field to mesh", job.frame.input.string(), 0, "scene",
               "mesh a scene .toml with [scene] map or graph");
  if (in.scene.graph_alone && job.planes)
    fail_input("--planes has no effect on a graph file alone: it has no [[planes]], and its floor is for images",
               job.frame.input.string(), 0, "--planes", "mesh a scene .toml whose [[planes]] name the ground");
  drop_floor(in.scene);  // a graph file alone meshes as the graph only
  return in;
}

// The files, with SIGINT and SIGTERM removing each one's temporary, and an
// OBJ's .mtl when it is new: it was written first and would name no OBJ.
void write_files(const MeshJob& job, const Scene& scene, const std::optional<LevelSetBand>& band,
                 const std::optional<TriMesh>& mesh, MeshReport& r) {
  const std::vector<fs::path> files = mesh_files(job.output);
  std::error_code ec;
  const bool new_mtl = files.size() > 1 && !fs::exists(job.output, ec) && output_kind(files[1]) == OutputKind::replace;
  const RemoveTempOnSignal output_temp(job.output);
  std::optional<RemoveTempOnSignal> mtl_temp, mtl_file;  // destroyed before output_temp, as the guards nest
  if (files.size() > 1) mtl_temp.emplace(files[1]);
  if (new_mtl) mtl_file.emplace(files[1], RemoveTempOnSignal::Remove::file);
  if (band) r.band_voxels = write_level_set(*band, job.output);
  else write_mesh(*mesh, materials_of(scene), job.output);
  mtl_file.reset();  // the OBJ landed: its .mtl stays
  for (const fs::path& f : files) r.written.push_back(f.string());
}

}  // namespace

std::vector<fs::path> mesh_files(const fs::path& file) {
  std::vector<fs::path> files{file};
  if (mesh_format_for(file) == MeshFormat::obj) files.push_back(fs::path(file).replace_extension(".mtl"));
  return files;
}

MeshReport mesh_scene(const MeshJob& job, FrameSession& session, const MeshProgress& progress) {
  const auto start = Clock::now();
  // From here on the export has job.frame.timeout seconds: checked between
  // stages, and a watchdog ends the process if a dispatch never returns.
  const std::string what = job.frame.label.empty() ? "the mesh export" : job.frame.label;
  GuardedJob timeout(job.frame.timeout, what);
  const MeshProgress step = [&](const char* stage, double fraction) {
    timeout.check();
    if (progress) progress(stage, fraction);
  };
  MeshReport r;
  LoadedInput in;
  checked_input(job, in, r);
  const float time = job.frame.time ? *job.frame.time : in.scene.render.time;
  pose_graph_at(in.scene, time);  // an animated graph's nodes at this time: its box, and the mesh's, move with them
  const Scene& scene = in.scene;
  MeshBox box;
  const FieldClip clip = clip_for(job, scene, box);
  check_voxel(job, box);
  const MeshGrid grid = mesh_grid(glm::dvec3(box.min), glm::dvec3(box.max), job.resolution, job.voxel);
  r.cells = grid.cells;
  r.voxel = grid.voxel;
  AssembleOptions opts = job.frame.assemble_options();
  opts.field_sampler = true;
  prepare_graph_shape(scene, opts);  // once: the sampler's map() and the GraphField take it from here
  const ShaderSource src = assemble_scene(scene, opts);

  session.context(job.frame.backend);
  const Program prog(Program::Compute{}, src);
  std::unique_ptr<GraphField> field;
  if (opts.graph && opts.graph->plan.interpret) {
    field = std::make_unique<GraphField>(*opts.graph, nullptr, true);
    field->bind();
    if (job.frame.verbose && !field->summary().empty()) std::fprintf(stderr, "  %s\n", field->summary().c_str());
  }
  r.setup_s = seconds_since(start);
  // Every uniform a frame at this time would set (a map() may read the
  // materials or lights, not only uTime); uFrame as a still's at 24 fps.
  set_scene_uniforms(prog, animated(scene, time), 1, 1, time, static_cast<int>(std::lround(time * kSceneFps)));
  FieldSampler sampler(prog, {glm::vec3(grid.origin), static_cast<float>(grid.voxel)}, clip, time);
  SparseOptions so;
  so.lipschitz = std::max(scene.quality.lipschitz, 1e-3f);
  so.band = r.format == MeshFormat::vdb ? static_cast<float>(job.band) : 0.0f;
  so.progress = step;
  so.bricks_ahead = [&job](double bricks) { check_memory(bricks, job); };
  const SparseField sparse = sample_sparse(sampler, grid, so);
  r.bricks = sparse.bricks.size();
  r.nonfinite = sparse.nonfinite;
  NonfiniteGuard guard{job.frame.input.string(), job.frame.strict, {}, "nothing written", "samples of map()"};
  if (job.frame.label.rfind("frame ", 0) == 0) guard.where = job.frame.label;
  guard_nonfinite(guard, static_cast<long long>(sparse.nonfinite), static_cast<long long>(sparse.samples));
  r.sample_s = seconds_since(start);
  std::optional<LevelSetBand> band;
  std::optional<TriMesh> mesh;
  if (r.format == MeshFormat::vdb) {
    band = band_of(sparse, scene, job.band);
  } else {
    mesh = mesh_of(sampler, sparse, scene, job, step, r);
  }
  r.samples = sampler.evaluations();
  r.readback_bytes = sampler.readback_bytes();
  step("writing", 0.9);
  // The write is atomic, and not cut short by the watchdog: no temporary is left.
  timeout.finish();
  const auto w = Clock::now();
  if (!job.output.empty()) write_files(job, scene, band, mesh, r);
  if (job.mesh_out && mesh) *job.mesh_out = std::move(*mesh);
  r.write_s = seconds_since(w);
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace ms
