// The viewer's mesh export (docs/viewer.md#exporting-a-mesh): the scene as
// it stands -- the panel's ranged uniforms, the time, the flags that change
// the field -- meshed by `marchstudio mesh` run as a child of this same
// binary. A child, not a call: a scene that crashes the driver, exhausts
// memory or hangs the mesher takes only the child down, and the window
// keeps drawing while it works (M polls it each frame; --mesh-on-exit
// waits for it).
//
//   MeshExportSpec spec = ...;               // typed, from the viewer's state
//   MeshExport job;
//   job.start(spec);                         // throws ms::Error (system)
//   if (auto r = job.poll()) say(r->line);   // each frame
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/overrides.h"
#include "shader/assemble.h"
#include "shader/scene_params.h"

namespace ms::live {

// What the field depends on at the moment of the export.
struct MeshExportSpec {
  std::filesystem::path input;   // the scene, as the viewer was given it
  std::filesystem::path output;  // its extension picks the format
  int resolution = 256;          // cells along the box's longest side
  double time = 0.0;             // the scene time shown
  // The shader dir, -D, --allow-include, --graph-eval, --no-prune, and the
  // --uniform values the viewer started with (already the panel's initials).
  AssembleOptions assemble;
  SceneOverrides set;            // --set
  std::string preset;            // empty: the file's
  std::vector<SceneParam> params;  // the panel's values now; those moved from their initial are passed
};

// The child's arguments after the program name, in one place: every
// typed value of `spec` turned into the flag `mesh` reads it from.
std::vector<std::string> mesh_export_args(const MeshExportSpec& spec);

// `dir`/`stem`_mesh_NNN.obj for the first NNN >= 001 that does not exist.
std::filesystem::path next_mesh_path(const std::filesystem::path& dir, const std::string& stem);

struct MeshExportResult {
  bool ok = false;
  int exit_code = 0;  // the child's; 128 + N when signal N ended it
  std::string line;   // "wrote X (N triangles, watertight)", or the child's error without "marchstudio: "
};

// The result from the child's exit code and its captured stdout (the
// --json report) and stderr (the one-line error).
MeshExportResult mesh_export_result(int exit_code, const std::string& out, const std::string& err,
                                    const std::filesystem::path& output);

// One child at a time. Its stdout and stderr go to unlinked temporary
// files, so a chatty child can never block on a full pipe while the viewer
// is busy drawing.
class MeshExport {
 public:
  MeshExport() = default;
  MeshExport(const MeshExport&) = delete;
  MeshExport& operator=(const MeshExport&) = delete;
  // A child still running is waited for: the file it writes is the user's.
  ~MeshExport();

  // Throws ms::Error (system) when no child can be started.
  void start(const MeshExportSpec& spec);
  bool running() const { return pid_ > 0; }
  const std::filesystem::path& output() const { return output_; }
  // The result once the child has exited; nothing while it runs (or none ran).
  std::optional<MeshExportResult> poll();
  // Blocks until the child exits.
  MeshExportResult wait();

 private:
  MeshExportResult finish(int status);
  pid_t pid_ = -1;
  int out_fd_ = -1, err_fd_ = -1;
  std::filesystem::path output_;
};

// start() then wait(): --mesh-on-exit. Never throws.
MeshExportResult export_mesh_now(const MeshExportSpec& spec);

}  // namespace ms::live
