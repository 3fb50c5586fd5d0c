// live/mesh_export.h: the viewer's mesh export, without a window: the
// child's argument list built from the viewer's typed state, the result
// read from the child's exit code and output, and the next free file name.
// tests/cli/test_viewer_mesh.cpp runs the real child under Xvfb.
#include <gtest/gtest.h>

#include <algorithm>

#include "files.h"
#include "live/live_values.h"
#include "live/mesh_export.h"

namespace ms::live {
namespace {

SceneParam param(const std::string& name, int components, std::array<float, 4> initial, std::array<float, 4> value,
                 bool is_int = false) {
  SceneParam p;
  p.name = name;
  p.components = components;
  p.is_int = is_int;
  p.initial = initial;
  p.value = value;
  return p;
}

SceneOverride set_flag(const std::string& key, toml::array value) {
  SceneOverride o;
  o.flag = "--set " + key;
  o.value = std::move(value);
  return o;
}

TEST(LiveMeshExport, TheChildsFlagsFollowTheViewersState) {
  MeshExportSpec s;
  s.input = "scenes/seed.toml";
  s.output = "seed_mesh_001.obj";
  s.resolution = 64;
  s.time = -2.5;
  s.assemble.shader_dir = "/opt/sdf";
  s.assemble.allow_include = {"/inc"};
  s.assemble.defines = {{"FOO", "2"}};
  s.assemble.graph_eval = GraphEval::interpreter;
  s.assemble.prune = false;
  s.preset = "fast";
  toml::array fov, name, color;
  fov.push_back(30.0);
  name.push_back("it's");
  color.push_back(toml::array{1, 0, 0});
  s.set = {set_flag("camera.fov", fov), set_flag("scene.name", name), set_flag("materials.ball.color", color)};
  s.assemble.uniforms = {{"uStart", {0.5}}, {"uMoved", {0.25}}};
  s.params = {param("uStart", 1, {0.5f}, {0.5f}),                       // as it started: its --uniform stays
              param("uMoved", 1, {0.25f}, {0.75f}),                     // moved: the panel's value wins
              param("uStill", 1, {1.0f}, {1.0f}),                       // never moved: no flag
              param("uCount", 1, {4.0f}, {7.0f}, true),                 // an int stays whole
              param("uTint", 3, {1.0f, 1.0f, 1.0f}, {1.0f, 0.5f, 0.25f})};
  const std::vector<std::string> want = {
      "mesh", "scenes/seed.toml", "--output=seed_mesh_001.obj", "--json", "--resolution=64", "--time=-2.5",
      "--shader-dir=/opt/sdf", "--allow-include=/inc", "--define=FOO=2", "--graph-eval=interpreter", "--no-prune",
      "--preset=fast", "--set=camera.fov=30.0", "--set=scene.name=\"it's\"", "--set=materials.ball.color=[ 1, 0, 0 ]",
      "--uniform=uStart=0.5", "--uniform=uMoved=0.75", "--uniform=uCount=7", "--uniform=uTint=[1,0.5,0.25]"};
  EXPECT_EQ(mesh_export_args(s), want);
}

TEST(LiveMeshExport, DefaultsAddNoFlags) {
  MeshExportSpec s;
  s.input = "a.toml";
  s.output = "a.ply";
  s.params = {param("uR", 1, {0.6f}, {0.6f})};
  const std::vector<std::string> want = {"mesh", "a.toml", "--output=a.ply", "--json", "--resolution=256",
                                         "--time=0"};
  EXPECT_EQ(mesh_export_args(s), want);
}

TEST(LiveMeshExport, TheResultIsOneLine) {
  const auto ok = mesh_export_result(0, R"({"schema":"marchstudio.mesh/1","triangles":1234,"manifold":true})" "\n",
                                     "", "seed_mesh_001.obj");
  EXPECT_TRUE(ok.ok);
  EXPECT_EQ(ok.line, "wrote seed_mesh_001.obj (1234 triangles, watertight)");
  const auto open = mesh_export_result(0, R"({"triangles":8,"manifold":false})", "", "x.stl");
  EXPECT_EQ(open.line, "wrote x.stl (8 triangles, NOT watertight)");
  const auto bad = mesh_export_result(
      2, "", "marchstudio: x.toml: warning: something\nmarchstudio: x.glsl: a Shadertoy shader has no map()\n", "x.obj");
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.line, "x.glsl: a Shadertoy shader has no map()");
  const auto killed = mesh_export_result(137, "", "", "x.obj");
  EXPECT_FALSE(killed.ok);
  EXPECT_EQ(killed.line, "the mesh export died (signal 9)");
  EXPECT_EQ(mesh_export_result(3, "", "garbage\n", "x.obj").line, "the mesh export failed (exit 3)");
}

TEST(LiveMeshExport, TheNextFileNeverOverwrites) {
  test::TempDir dir;
  EXPECT_EQ(next_mesh_path(dir.path(), "seed"), dir.path() / "seed_mesh_001.obj");
  test::write_file(dir.path() / "seed_mesh_001.obj", "");
  test::write_file(dir.path() / "seed_mesh_003.obj", "");
  EXPECT_EQ(next_mesh_path(dir.path(), "seed"), dir.path() / "seed_mesh_002.obj");
}

TEST(LiveMeshExport, AScriptedDragMovesAUniform) {
  Scene scene;
  std::vector<SceneParam> params = {param("uR", 1, {0.6f}, {0.6f}), param("uN", 1, {2.0f}, {2.0f}, true)};
  ScriptedDrag d;
  d.target = "uR";
  d.uniform = true;
  d.to = {1.0, 0.0, 0.0};
  d.first = 2;
  d.last = 6;
  EXPECT_FALSE(d.apply(scene, params, 1));
  EXPECT_FLOAT_EQ(params[0].value[0], 0.6f);
  EXPECT_TRUE(d.apply(scene, params, 2));
  EXPECT_TRUE(d.apply(scene, params, 4));
  EXPECT_FLOAT_EQ(params[0].value[0], 0.8f);
  EXPECT_TRUE(d.apply(scene, params, 6));
  EXPECT_FLOAT_EQ(params[0].value[0], 1.0f);
  EXPECT_FALSE(d.apply(scene, params, 7));
  EXPECT_FLOAT_EQ(params[0].value[0], 1.0f);
  ScriptedDrag n = d;
  n.target = "uN";
  n.to = {5.0, 0.0, 0.0};
  n.apply(scene, params, 2);
  n.apply(scene, params, 3);  // 2.75: whole, as the panel's int slider
  EXPECT_FLOAT_EQ(params[1].value[0], 3.0f);
}

}  // namespace
}  // namespace ms::live
