// The viewer's mesh exports (live/mesh_export.h): M and F8 start one in a
// child process and the loop polls it each frame; --mesh-on-exit runs one
// to the end once the window is gone.
#include <cstdio>

#include "live/viewer_app.h"

namespace ms::live {
namespace fs = std::filesystem;

MeshExportSpec Viewer::mesh_spec(const fs::path& output) {
  MeshExportSpec spec;
  spec.input = o_.input;
  spec.output = output;
  spec.resolution = o_.mesh_resolution;
  spec.time = s_.time;
  spec.assemble = o_.assemble;
  spec.set = o_.set;
  // The file's own preset needs no flag; one chosen at start or in the panel does.
  if (session_.preset() != session_.file_scene().quality.preset) spec.preset = session_.preset();
  spec.params = session_.params();
  return spec;
}

void Viewer::start_mesh() {
  if (mesh_.running()) return s_.say("mesh: still writing " + mesh_.output().string(), 4.0);
  const fs::path out = next_mesh_path(".", o_.input.stem().string()).lexically_normal();
  try {
    mesh_.start(mesh_spec(out));
  } catch (const Error& e) {
    return report_mesh(MeshExportResult{false, 3, e.what()});
  }
  log_.line("mesh writing " + out.string());
  s_.say("mesh: writing " + out.string() + " ...", 1e9);  // until the child is done
}

void Viewer::poll_mesh() {
  if (std::optional<MeshExportResult> r = mesh_.poll()) report_mesh(*r);
}

void Viewer::report_mesh(const MeshExportResult& r) {
  log_.line(r.ok ? "mesh " + r.line : "mesh failed -- " + r.line);
  if (!r.ok) std::fprintf(stderr, "marchstudio: %s\n", r.line.c_str());
  s_.say("mesh: " + r.line, r.ok ? 6.0 : 10.0);
}

int Viewer::finish_mesh(int code) {
  if (mesh_.running()) {
    log_.line("mesh waiting for " + mesh_.output().string());
    report_mesh(mesh_.wait());
  }
  if (!exit_mesh_) return code;
  const MeshExportResult r = export_mesh_now(*exit_mesh_);
  log_.line(r.ok ? "mesh " + r.line : "mesh failed -- " + r.line);
  // Without --log the log line above is on stderr already.
  if (!r.ok || !o_.log_file.empty()) std::fprintf(stderr, "marchstudio: %s\n", r.line.c_str());
  return r.ok ? code : 3;
}

}  // namespace ms::live
