// A scene's graph file as input, through the real binary: read only from
// the scene's folder and --allow-include, judged where its symlinks lead,
// so a path out of the folder, an absolute one and a symlink out are each
// one line, exit 2, no output and nothing of the foreign file echoed, by
// render, mesh and --jobs; a file of a million '[' or of millions of
// containers is refused by name within a capped address space; a huge key
// is cut in the error line.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kLimit = address_space_limit(2000000);

const std::string kSphere = "{\"root\": {\"sdf\": \"sdSphere\", \"r\": 0.5}}\n";

std::string scene_toml(const std::string& graph) {
  return "[scene]\nname = \"g\"\ngraph = \"" + graph + "\"\n[render]\nwidth = 8\nheight = 8\n"
         "[[materials]]\nname = \"m\"\n";
}

// <tmp>/scene holds the scenes; <tmp>/outside a file nothing may read
// unless --allow-include names it, its first key a secret that must never
// reach an error line.
struct Layout {
  TempDir dir;
  Layout() {
    write_file(dir / "outside" / "x.json", "{\"SECRET_KEY\": {\"sdf\": \"sdSphere\", \"r\": 0.5}}\n");
    write_file(dir / "outside" / "ok.json", kSphere);
    write_file(dir / "scene" / "parent.toml", scene_toml("../outside/x.json"));
    write_file(dir / "scene" / "absolute.toml", scene_toml((dir / "outside" / "x.json").string()));
    write_file(dir / "scene" / "passwd.toml", scene_toml("/etc/passwd"));
    fs::create_symlink("../outside/x.json", dir / "scene" / "link.json");
    write_file(dir / "scene" / "link.toml", scene_toml("link.json"));
  }
  RunResult run(const std::string& command, const std::string& scene, const std::string& out,
                std::vector<std::string> more = {}) {
    std::vector<std::string> args = {command, "scene/" + scene, "-o", out};
    if (command == "render") args.insert(args.end(), {"--size", "8x8"});
    else args.insert(args.end(), {"--resolution", "16"});
    args.insert(args.end(), more.begin(), more.end());
    return run_marchstudio(args, dir.path());
  }
};

// One line naming the scene, its key and the rule; nothing read out there.
void expect_confined(const RunResult& r, const std::string& scene) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("marchstudio: scene/" + scene + ":3: scene.graph: the graph file '"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("is outside the directories includes may read"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-include"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("SECRET"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("malformed"), std::string::npos) << r.err;  // /etc/passwd was parsed
}

TEST(GraphConfine, EveryWayOutOfTheScenesFolderIsRefusedByRenderAndMesh) {
  Layout l;
  for (const std::string scene : {"parent.toml", "absolute.toml", "passwd.toml", "link.toml"}) {
    SCOPED_TRACE(scene);
    expect_confined(l.run("render", scene, "o.png"), scene);
    EXPECT_FALSE(fs::exists(l.dir / "o.png"));
    expect_confined(l.run("mesh", scene, "o.obj"), scene);
    EXPECT_FALSE(fs::exists(l.dir / "o.obj"));
  }
}

TEST(GraphConfine, ABatchJobIsRefusedAloneAndAllowIncludeLetsTheFileIn) {
  Layout l;
  write_file(l.dir / "jobs.jsonl", "{\"scene\": \"scene/link.toml\", \"output\": \"j.png\"}\n");
  const RunResult jobs = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "8x8"}, l.dir.path());
  EXPECT_EQ(jobs.exit_code, 2) << jobs.err;
  EXPECT_NE(jobs.err.find("marchstudio: jobs.jsonl:1: scene/link.toml:3: scene.graph: the graph file"),
            std::string::npos) << jobs.err;
  EXPECT_EQ(jobs.err.find("SECRET"), std::string::npos) << jobs.err;
  EXPECT_FALSE(fs::exists(l.dir / "j.png"));
  // The same rule as includes: --allow-include widens it.
  write_file(l.dir / "scene" / "allowed.toml", scene_toml("../outside/ok.json"));
  expect_confined(l.run("render", "allowed.toml", "o.png"), "allowed.toml");
  const RunResult ok = l.run("render", "allowed.toml", "o.png", {"--allow-include", "outside"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(l.dir / "o.png"));
}

// Refused by name in seconds, in an address space the old reader (about
// 90 bytes a byte of '[') outgrew: exit 2, not the allocator's exit 3.
RunResult expect_refused_in_budget(const fs::path& dir, const std::string& json, const std::string& command) {
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r =
      run_marchstudio({command, "s.toml", "-o", command == "mesh" ? "o.obj" : "o.png"}, dir, kLimit);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 500);
  EXPECT_EQ(r.err.rfind("marchstudio: " + (dir / json).string() + ":", 0), 0u) << r.err.substr(0, 500);
  EXPECT_EQ(count_of(r.err, "\n"), 1) << r.err.substr(0, 500);
  EXPECT_LT(seconds, 30.0);
  EXPECT_FALSE(fs::exists(dir / "o.png"));
  EXPECT_FALSE(fs::exists(dir / "o.obj"));
  return r;
}

TEST(GraphMemory, AFileOfFortyMillionBracketsIsRefusedByNameBeforeItIsRead) {
  TempDir dir;
  write_file(dir / "deep.json", std::string(40u << 20, '['));
  write_file(dir / "s.toml", scene_toml((dir / "deep.json").string()));
  for (const char* command : {"render", "mesh"}) {
    SCOPED_TRACE(command);
    const RunResult r = expect_refused_in_budget(dir.path(), "deep.json", command);
    EXPECT_NE(r.err.find("nested up to 41943040 deep), over the "), std::string::npos) << r.err.substr(0, 500);
    EXPECT_NE(r.err.find("memory budget"), std::string::npos) << r.err.substr(0, 500);
  }
}

TEST(GraphMemory, TenMillionContainersAreReadInLinearMemoryAndRefusedByName) {
  TempDir dir;
  std::string json = "{\"root\": {\"op\": \"opUnion\", \"children\": [";
  for (int i = 0; i < 10000000; ++i) json += "{},";
  json += "{}]}}\n";
  write_file(dir / "count.json", json);
  write_file(dir / "s.toml", scene_toml((dir / "count.json").string()));
  expect_refused_in_budget(dir.path(), "count.json", "render");
}

TEST(GraphErrors, AMegabyteKeyIsCutInTheErrorLine) {
  TempDir dir;
  const std::string key(1 << 20, 'k');
  write_file(dir / "g.json", "{\"root\": {\"sdf\": \"sdSphere\", \"r\": 0.5, \"" + key + "\": 1}}\n");
  write_file(dir / "s.toml", scene_toml("g.json"));
  const RunResult r = run_marchstudio({"render", "s.toml", "--size", "8x8", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find(":1: /root/kkkk"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("kkk...: unknown key 'kkkk"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

}  // namespace
}  // namespace ms::test
