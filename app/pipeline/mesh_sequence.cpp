#include "pipeline/mesh_sequence.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "core/clock.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/version.h"
#include "io/atomic_file.h"
#include "io/file_stamp.h"
#include "io/input_file.h"
#include "pipeline/fingerprint.h"
#include "pipeline/input.h"
#include "pipeline/progress.h"
#include "pipeline/still_job.h"
#include "shader/assemble.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// The files frame f is made of (mesh_files(): an OBJ's .mtl too), which a
// complete frame needs every one of.
std::vector<fs::path> frame_parts(const fs::path& file) { return mesh_files(file); }

// Frame numbers only (a path is made when needed): a range of 10^8 frames
// is 0.4 GB of them, as render --frames holds, not gigabytes of paths.
struct Scan {
  std::vector<int> todo, skipped;
  std::vector<std::pair<int, std::string>> redone;    // frame, why
};

// A killed run's temporaries of the range's files, a chunk of frames at a
// time for the same reason.
void sweep_dead_temps(const MeshSequenceJob& job) {
  constexpr std::size_t kChunk = 8192;
  std::vector<fs::path> files;
  for (int f = job.range.first; f <= job.range.last; ++f) {
    for (const fs::path& p : frame_parts(job.pattern.path(f))) files.push_back(p);
    if (files.size() >= kChunk || f == job.range.last) {
      say_removed_temps(files);
      files.clear();
    }
  }
}

Scan scan_frames(const MeshSequenceJob& job, const std::string& job_fp) {
  Scan s;
  for (int f = job.range.first; f <= job.range.last; ++f) {
    const fs::path path = job.pattern.path(f);
    if (job.force) {
      s.todo.push_back(f);
      continue;
    }
    const float time = static_cast<float>(static_cast<double>(f) / job.fps);
    std::string why;
    const StampCheck c = check_stamp(path, frame_parts(path), frame_fingerprint(job_fp, f, time), &why);
    if (c == StampCheck::complete) {
      s.skipped.push_back(f);
      continue;
    }
    s.todo.push_back(f);
    if (c != StampCheck::missing) s.redone.emplace_back(f, why);
  }
  return s;
}

// Frame f meshed and written, under its own --timeout (as each frame of a
// render sequence has: mesh_scene() keeps it), then stamped.
MeshReport mesh_frame(const MeshSequenceJob& job, FrameSession& session, int f, const std::string& job_fp) {
  MeshJob m = job.mesh;
  m.output = job.pattern.path(f);
  const float time = static_cast<float>(static_cast<double>(f) / job.fps);
  m.frame.time = time;
  // The old stamp goes first: a run killed between the new file and its
  // stamp leaves a file no stamp vouches for, which the next run redoes.
  m.frame.label = "frame " + std::to_string(f);  // names it in a --timeout's error
  remove_stamp(m.output);
  const MeshReport r = mesh_scene(m, session);
  // A FIFO or a device is written through (io/atomic_file.h): nothing stays
  // there for a stamp to vouch for, nor a file to read back.
  const std::vector<fs::path> parts = frame_parts(m.output);
  if (std::all_of(parts.begin(), parts.end(), [](const fs::path& p) { return output_kind(p) == OutputKind::replace; }))
    write_stamp(m.output, parts, frame_fingerprint(job_fp, f, time));
  return r;
}

}  // namespace

std::string mesh_job_fingerprint(const MeshJob& job) {
  const FrameJob& fj = job.frame;
  const LoadedInput in = load_input_scene(fj.input, fj.disable, fj.assemble_options(), fj.preset, fj.set);
  Hash128 h;
  h.add(std::string(kSoftware) + " mesh fingerprint 1");
  h.add(read_input_file(in.path, "input file", {}, kMaxTextInput));
  for (const SceneOverride& o : in.overrides) {
    std::ostringstream value;
    value << o.value;
    h.add(o.flag).add(value.str());
  }
  // A Shadertoy input has no field: mesh_scene() refuses it with the reason.
  if (!in.shadertoy) {
    AssembleOptions opts = fj.assemble_options();
    opts.field_sampler = true;
    prepare_graph_shape(in.scene, opts);
    h.add(assemble_scene(in.scene, opts).text);
    if (opts.graph) {
      const GraphBuffers& b = opts.graph->buffers;
      h.add_bytes(b.nodes.data(), b.nodes.size() * sizeof b.nodes[0]);
      h.add_bytes(b.floats.data(), b.floats.size() * sizeof b.floats[0]);
      h.add_bytes(b.program.data(), b.program.size() * sizeof b.program[0]);
      h.add(opts.graph->plan.pruned());
    }
  }
  h.add(job.resolution).add(job.voxel).add(job.bounds.has_value()).add(job.planes).add(job.band);
  if (job.bounds)
    for (const glm::vec3& v : {job.bounds->min, job.bounds->max}) h.add(v.x).add(v.y).add(v.z);
  h.add(static_cast<int>(fj.graph_eval)).add(fj.prune);
  return h.hex();
}

MeshSequenceReport mesh_sequence(const MeshSequenceJob& job, FrameSession& session, bool tty) {
  const Clock::time_point start = Clock::now();
  const fs::path first = job.pattern.path(job.range.first);
  if (!mesh_format_for(first))
    fail_input("cannot tell the mesh format of '" + job.pattern.text() + "'", {}, 0, "-o",
               "name the output .obj, .ply, .stl, .glb or .vdb");
  output_kind(first, "-o");
  check_output_directory(first.parent_path(), "-o");
  const std::string job_fp = mesh_job_fingerprint(job.mesh);
  sweep_dead_temps(job);
  const Scan scan = scan_frames(job, job_fp);

  Progress progress(static_cast<int>(scan.todo.size()), tty, stderr, "frames", "meshed");
  for (int f : scan.skipped) progress.skipped(f, job.pattern.path(f).string());
  for (const auto& [f, why] : scan.redone)
    progress.line("frame " + std::to_string(f) + ": " + job.pattern.path(f).string() + " is not a complete frame (" +
                  why + "), meshing it again");
  MeshSequenceReport r;
  r.skipped = static_cast<int>(scan.skipped.size());
  progress.start();
  for (int f : scan.todo) {
    const Clock::time_point t0 = Clock::now();
    const MeshReport m = mesh_frame(job, session, f, job_fp);
    progress.rendered(f, seconds_since(t0));
    ++r.meshed;
    for (const std::string& path : m.written) std::printf("%s\n", path.c_str());
    std::fflush(stdout);
    if (job.mesh.frame.verbose) progress.line(mesh_summary(m));
    if (!m.check.ok() && m.format != MeshFormat::vdb)
      progress.line("warning: " + m.output + ": the mesh check found " + m.check.summary());
  }
  progress.finish();
  r.seconds = seconds_since(start);
  char summary[160];
  std::snprintf(summary, sizeof summary, "mesh sequence: %d of %d frames meshed, %d skipped, %.2f s", r.meshed,
                job.range.count(), r.skipped, r.seconds);
  progress.line(summary);
  return r;
}

}  // namespace ms
