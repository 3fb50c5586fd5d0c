// `marchstudio mesh` through the real binary on llvmpipe (docs/mesh.md):
// the library's exact primitives at --resolution 256 land within 0.05
// voxel of their analytic surfaces, a box's corners within 0.1 voxel of
// the true corners, every mesh passes the check, every format is written,
// and bad input is one line, a non-zero exit and no file.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_read.h"
#include "run.h"

namespace ms::test {
namespace {

// A scene of one map() (`body` returns its distance), material "part",
// inside `bounds` (a TOML [bounds] body).
std::filesystem::path scene(const TempDir& dir, const std::string& name, const std::string& body,
                            const std::string& bounds) {
  write_file(dir / (name + ".glsl"), "vec2 map(vec3 p) {\n" + body + "\n}\n");
  write_file(dir / (name + ".toml"), "[scene]\nname = \"" + name + "\"\nmap = \"" + name +
                                          ".glsl\"\n\n[bounds]\n" + bounds +
                                          "\n\n[[materials]]\nname = \"part\"\ncolor = [0.7, 0.7, 0.75]\n");
  return dir / (name + ".toml");
}

struct Exported {
  ReadMesh mesh;
  nlohmann::json report;
};

Exported export_mesh(const std::filesystem::path& scene_file, const TempDir& dir, int resolution) {
  const std::filesystem::path out = dir / "out.ply";
  const RunResult r = run_marchstudio(
      {"mesh", scene_file.string(), "-o", out.string(), "--resolution", std::to_string(resolution), "--json"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  Exported e;
  e.report = nlohmann::json::parse(r.out);
  e.mesh = read_ply(out);
  EXPECT_TRUE(e.report["manifold"].get<bool>()) << e.report["check"]["summary"];
  EXPECT_TRUE(e.mesh.ok);
  EXPECT_EQ(e.report["vertices"].get<std::size_t>(), distinct_positions(e.mesh));
  return e;
}

double worst(const Exported& e, const std::function<double(const glm::vec3&)>& d) {
  double w = 0.0;
  for (const glm::vec3& v : e.mesh.positions) w = std::max(w, std::abs(d(v)));
  return w / e.report["voxel"].get<double>();
}

float sd_box(const glm::vec3& p, const glm::vec3& b) {
  const glm::vec3 q = glm::abs(p) - b;
  return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

TEST(Mesh, TheSeedSphereLiesOnItsRadius) {
  TempDir dir;
  const Exported e = export_mesh(source_dir() / "scenes/seed.toml", dir, 256);
  EXPECT_LT(worst(e, [](const glm::vec3& v) { return glm::length(v - glm::vec3(0, 1, 0)) - 1.0; }), 0.05);
  EXPECT_EQ(e.report["check"]["euler"].get<int>(), 2);
  EXPECT_LT(e.report["hausdorff_voxels"].get<double>(), 0.1);
  // Sparse: the 264^3 grid's corners are 18.6 million.
  EXPECT_LT(e.report["samples"].get<double>(), 18.6e6);
}

TEST(Mesh, AnOffGridBoxKeepsItsCorners) {
  TempDir dir;
  const glm::vec3 c(0.0131f, 0.0207f, -0.0093f), b(0.613f, 0.427f, 0.371f);
  const auto f = scene(dir, "box",
                       "  return vec2(sdBox(p - vec3(0.0131, 0.0207, -0.0093), vec3(0.613, 0.427, 0.371)), MAT_PART);",
                       "min = [-0.7, -0.5, -0.45]\nmax = [0.7, 0.5, 0.45]");
  const Exported e = export_mesh(f, dir, 256);
  const double voxel = e.report["voxel"].get<double>();
  EXPECT_LT(worst(e, [&](const glm::vec3& v) { return sd_box(v - c, b); }), 0.05);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner = c + b * glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    float best = 1e9f;
    for (const glm::vec3& v : e.mesh.positions) best = std::min(best, glm::length(v - corner));
    EXPECT_LT(best / voxel, 0.1) << "corner " << k;
  }
}

TEST(Mesh, ABoxMinusACylinderMatchesItsAnalyticDistance) {
  TempDir dir;
  const auto f = scene(dir, "cut",
                       "  float box = sdBox(p - vec3(0.011, 0.0, 0.007), vec3(0.6, 0.3, 0.4));\n"
                       "  float hole = sdCylinder(p - vec3(0.15, 0.0, 0.05), 0.2137, 0.5);\n"
                       "  return vec2(max(box, -hole), MAT_PART);",
                       "min = [-0.65, -0.35, -0.45]\nmax = [0.65, 0.35, 0.45]");
  const Exported e = export_mesh(f, dir, 256);
  const auto d = [](const glm::vec3& v) {
    const float box = sd_box(v - glm::vec3(0.011f, 0.0f, 0.007f), glm::vec3(0.6f, 0.3f, 0.4f));
    const glm::vec3 q = v - glm::vec3(0.15f, 0.0f, 0.05f);
    const glm::vec2 w = glm::abs(glm::vec2(glm::length(glm::vec2(q.x, q.z)), q.y)) - glm::vec2(0.2137f, 0.5f);
    const float hole = std::min(std::max(w.x, w.y), 0.0f) + glm::length(glm::max(w, 0.0f));
    return static_cast<double>(std::max(box, -hole));
  };
  EXPECT_LT(worst(e, d), 0.05);
  // A box with a hole through it: genus 1.
  EXPECT_EQ(e.report["check"]["euler"].get<int>(), 0);
}

TEST(Mesh, PlanesJoinTheSolidOnlyWhenAsked) {
  TempDir dir;
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  const std::vector<std::string> box = {"--bounds", "-1.5,-0.5,-1.5,1.5,2.1,1.5", "--resolution", "48", "--json"};
  auto lowest = [&](const std::vector<std::string>& extra, nlohmann::json& report) {
    std::vector<std::string> args = {"mesh", seed, "-o", (dir / "p.ply").string()};
    args.insert(args.end(), box.begin(), box.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    report = nlohmann::json::parse(r.out);
    float y = 1e9f;
    for (const glm::vec3& v : read_ply(dir / "p.ply").positions) y = std::min(y, v.y);
    return y;
  };
  nlohmann::json without, with;
  // The ball alone rests on y = 0; with --planes the floor is a slab down to the box.
  EXPECT_GT(lowest({}, without), -0.01f);
  EXPECT_LT(lowest({"--planes"}, with), -0.49f);
  EXPECT_TRUE(with["manifold"].get<bool>()) << with["check"]["summary"];
  EXPECT_GT(with["triangles"].get<int>(), without["triangles"].get<int>());
}

TEST(Mesh, AFieldThatIsNaNInPlacesGivesFiniteVertices) {
  TempDir dir;
  // NaN on the +x half: the sphere is cut there, never a NaN vertex.
  const auto f = scene(dir, "nan",
                       "  float bad = sqrt(-1.0 - abs(p.y));\n"
                       "  return vec2(p.x > 0.013 ? bad : length(p) - 0.5, MAT_PART);",
                       "min = [-0.6, -0.6, -0.6]\nmax = [0.6, 0.6, 0.6]");
  const RunResult r = run_marchstudio({"mesh", f.string(), "-o", (dir / "n.ply").string(), "--resolution", "48"},
                                      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ReadMesh p = read_ply(dir / "n.ply");
  ASSERT_FALSE(p.positions.empty());
  for (const glm::vec3& v : p.positions) ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

TEST(Mesh, EveryFormatIsWritten) {
  TempDir dir;
  for (const char* ext : {"obj", "ply", "stl", "glb", "vdb"}) {
    const std::filesystem::path out = dir / (std::string("seed.") + ext);
    const RunResult r = run_marchstudio(
        {"mesh", (source_dir() / "scenes/seed.toml").string(), "-o", out.string(), "--resolution", "32"}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    EXPECT_GT(std::filesystem::file_size(out), 100u) << ext;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "seed.mtl"));
}

TEST(Mesh, BadInputIsOneLineAndNoFile) {
  TempDir dir;
  write_file(dir / "toy.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  const auto nobounds = scene(dir, "nob", "  return vec2(length(p) - 1.0, MAT_PART);", "");
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  write_file(dir / "file", "x");
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string says;
  } cases[] = {
      {{"mesh", (dir / "toy.glsl").string(), "-o", (dir / "a.obj").string()}, 2, "no map()"},
      {{"mesh", seed, "-o", (dir / "a.xyz").string()}, 2, "-o"},
      {{"mesh", nobounds.string(), "-o", (dir / "a.obj").string()}, 2, "bounds"},
      {{"mesh", seed, "-o", (dir / "a.obj").string(), "--bounds", "1,0,0,0,1,1"}, 2, "--bounds"},
      {{"mesh", seed, "-o", (dir / "file" / "a.obj").string(), "--resolution", "16"}, 3, "output directory"},
  };
  for (const Case& c : cases) {
    const RunResult r = run_marchstudio(c.args, dir.path());
    EXPECT_EQ(r.exit_code, c.code) << c.args[1] << " " << c.args[3] << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "a.obj"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a.xyz"));
}

TEST(Mesh, ATimeoutIsExitThreeAndNoFile) {
  TempDir dir;
  const RunResult r = run_marchstudio({"mesh", (source_dir() / "scenes/seed.toml").string(), "-o",
                                       (dir / "slow.ply").string(), "--resolution", "1024", "--timeout", "0.2"},
                                      dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("--timeout"), std::string::npos) << r.err;
  EXPECT_EQ(count_files(dir.path(), "slow"), 0);
}

TEST(Mesh, AGraphSceneThroughThePrunedInterpreter) {
  TempDir dir;
  const RunResult r = run_marchstudio({"mesh", (source_dir() / "tests/data/graph/part.toml").string(), "-o",
                                       (dir / "part.ply").string(), "--resolution", "96", "--graph-eval",
                                       "interpreter", "--json"},
                                      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["manifold"].get<bool>()) << j["check"]["summary"];
  EXPECT_LT(j["max_vertex_error_voxels"].get<double>(), 0.05);
}

}  // namespace
}  // namespace ms::test
