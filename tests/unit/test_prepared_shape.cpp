// A scene graph's prepared shape (its plan, buffers and pruning source,
// shader/assemble.h's GraphParts) is derived once per still and once per
// mesh: prepare() or mesh_scene() makes it, and every assembled shader and
// the GraphField take it from there. Counted by assemble_stats(), not timed.
// The still and mesh draw in a headless context (llvmpipe without a GPU).
#include <gtest/gtest.h>

#include <stdexcept>

#include "files.h"
#include "pipeline/mesh_job.h"
#include "pipeline/prepare.h"
#include "pipeline/shader_dir.h"
#include "pipeline/still_job.h"

namespace ms::test {
namespace {

// The part, interpreted and pruned: the path with buffers, a pruning pass
// and its GraphField (inline would skip them).
FrameJob part_job(const std::filesystem::path& output) {
  FrameJob job;
  job.input = source_dir() / "scenes/part.toml";
  job.output = output;
  job.shader_dir = resolve_shader_dir({});
  job.size = {64, 36};
  job.graph_eval = GraphEval::interpreter;
  job.verbose = true;  // its report assembles the scene's features too
  return job;
}

long shapes() { return assemble_stats().graph_parts.load(); }

TEST(PreparedShape, PrepareDerivesItOnceAndEveryPassReadsIt) {
  const TempDir dir;
  const long before = shapes();
  const PreparedFrame p = prepare(part_job(dir.path() / "part.png"), true);
  EXPECT_EQ(shapes() - before, 1);
  ASSERT_TRUE(p.opts.graph);
  EXPECT_TRUE(p.opts.graph->plan.pruned());
  EXPECT_FALSE(p.opts.graph->prune_src.text.empty());
  // Assembling again (features, a probe's variant) reads the same shape.
  (void)scene_features(p.in.scene, p.opts);
  (void)assemble_scene(p.in.scene, p.opts);
  EXPECT_EQ(shapes() - before, 1);
}

TEST(PreparedShape, AssemblingAGraphWithoutItIsAProgrammingError) {
  const TempDir dir;
  PreparedFrame p = prepare(part_job(dir.path() / "part.png"), true);
  p.opts.graph = nullptr;
  EXPECT_THROW((void)assemble_scene(p.in.scene, p.opts), std::logic_error);
}

TEST(PreparedShape, AStillDerivesItOnce) {
  const TempDir dir;
  const FrameJob job = part_job(dir.path() / "part.png");
  FrameSession session;
  const long before = shapes();
  render_still_job(job, session);  // load, -v, compile, GraphField, bounds, draw, write
  EXPECT_EQ(shapes() - before, 1);
  EXPECT_TRUE(std::filesystem::exists(job.output));
  ASSERT_NE(session.job().field(), nullptr);
  EXPECT_FALSE(session.job().field()->summary().empty());  // the pruning pass ran on the prepared grid
}

TEST(PreparedShape, AMeshDerivesItOnce) {
  const TempDir dir;
  MeshJob job;
  job.frame = part_job(dir.path() / "unused.png");
  job.frame.verbose = false;
  job.output = dir.path() / "part.obj";
  job.resolution = 24;
  FrameSession session;
  const long before = shapes();
  const MeshReport r = mesh_scene(job, session);
  EXPECT_EQ(shapes() - before, 1);
  EXPECT_GT(r.triangles, 0u);
}

}  // namespace
}  // namespace ms::test
