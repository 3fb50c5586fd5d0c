// `marchstudio mesh`: a scene's surface to a mesh (.obj .ply .stl .glb) or
// an OpenVDB level set (.vdb), headless (pipeline/mesh_job.h, docs/mesh.md).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/load_flags.h"
#include "gl/context.h"
#include "io/sequence.h"
#include "pipeline/input.h"
#include "pipeline/mesh_job.h"

namespace CLI {
class App;
}

namespace ms {

struct MeshArgs {
  std::string input;
  std::string output;        // not given: <input stem>.obj in the current directory
  int resolution = 256;      // cells along the box's longest side
  double voxel = 0.0;        // --voxel: the cell's size instead
  std::vector<float> bounds; // --bounds x0,y0,z0,x1,y1,z1
  bool planes = false;
  int band = 3;
  std::optional<double> time;  // none: the scene's
  std::optional<FrameRange> frames;  // --frames A..B: one file per frame
  std::optional<double> fps;   // none: kSceneFps
  bool force = false;        // --frames: mesh every frame again
  bool strict = false;       // NaN or Inf samples of map() are an error
  bool json = false;
  bool verbose = false;
  double timeout = 0.0;
  Backend backend = Backend::automatic;
  LoadFlags load;  // no --disable or Shadertoy options (cli/load_flags.h)
};

CLI::App* add_mesh_command(CLI::App& app, MeshArgs& args);
// The flags as a checked, typed job (a `render --jobs` mesh line's too:
// cli/job_list.h). Throws bad_input.
MeshJob make_mesh_job(const MeshArgs& args);
int run_mesh(const MeshArgs& args);

}  // namespace ms
