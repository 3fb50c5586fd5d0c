// An animated scene meshed at each frame of a range, one file per frame
// (`mesh --frames A..B -o out_%04d.obj`, docs/usage.md#mesh-sequences):
// frame f at time f / fps exactly, each through mesh_scene() in one
// session. A mesh has no room for an image's fingerprint, so each frame
// gets a stamp beside it (io/file_stamp.h) once it and its .mtl are
// written; a rerun skips a frame whose files match their stamp and whose
// stamp carries this run's fingerprint for that frame, and meshes again a
// missing, broken, stale or unstamped one (--force: every one).
//
//   MeshSequenceJob job;  job.mesh = ...;  job.range = {0, 9};
//   job.pattern = FramePattern("out/f_%04d.ply");
//   MeshSequenceReport r = mesh_sequence(job, session, isatty(2));  // throws ms::Error
#pragma once
#include <string>

#include "io/sequence.h"
#include "pipeline/frame_job.h"
#include "pipeline/frame_session.h"
#include "pipeline/mesh_job.h"

namespace ms {

struct MeshSequenceJob {
  MeshJob mesh;  // everything but mesh.output and mesh.frame.time, which each frame sets
  FrameRange range;
  FramePattern pattern{"frame_%04d.obj"};
  double fps = kSceneFps;
  bool force = false;  // mesh every frame again
};

struct MeshSequenceReport {
  int meshed = 0, skipped = 0;
  double seconds = 0.0;
};

// What makes every frame of `job` (pipeline/fingerprint.h's job part, for
// meshes): the scene file's bytes, its --set overrides, the field
// sampler's assembled shader (map, includes, defines, --uniform values),
// a graph's buffers, and the flags that shape the mesh. A frame adds its
// number and time (frame_fingerprint()).
std::string mesh_job_fingerprint(const MeshJob& job);

// Bad input (the pattern's format, the scene) throws before any file is
// touched; a failed write throws system with no partial file, the frames
// before it kept and stamped. Progress on stderr (pipeline/progress.h): a
// line per frame, or with `tty` a bar redrawn in place; each path written
// on stdout.
MeshSequenceReport mesh_sequence(const MeshSequenceJob& job, FrameSession& session, bool tty);

}  // namespace ms
