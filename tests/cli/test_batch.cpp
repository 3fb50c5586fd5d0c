// Batches through the real binary (cli/batch.h, docs/usage.md#batches):
// several inputs with --output-dir, and --jobs FILE, render in one process
// the same files, byte for byte, as one `render` per image; one bad job
// fails alone (its one-line error, the others written, exit 2 and a count);
// two inputs writing one file are refused before anything renders; the
// shared program cache compiles an identical shader once (counted from
// -v's "programs: N compiled, M from the cache" lines, never timed); a
// terminal gets a progress bar with an ETA, a log none.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include "run.h"

using namespace ms::test;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = source_dir() / "scenes";

// One `render` per image, the reference a batch must equal.
void render_one(const fs::path& scene, const fs::path& out, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"render", scene.string(), "-o", out.string()};
  args.insert(args.end(), more.begin(), more.end());
  const RunResult r = run_marchstudio(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

void expect_same_file(const fs::path& batch, const fs::path& single) {
  ASSERT_TRUE(fs::exists(batch)) << batch;
  ASSERT_TRUE(fs::exists(single)) << single;
  EXPECT_TRUE(read_file(batch) == read_file(single)) << batch << " differs from " << single;
}

int count_lines(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = 0; (at = text.find(needle, at)) != std::string::npos; at += needle.size()) ++n;
  return n;
}

}  // namespace

TEST(Batch, InputsWithOutputDirEqualSeparateRendersPngAndExr) {
  TempDir dir;
  const std::vector<std::string> stems = {"seed", "columns", "twist"};
  for (const std::string format : {"png", "exr"}) {
    const fs::path out = dir / ("batch_" + format);
    fs::create_directories(out);
    std::vector<std::string> args = {"render"};
    for (const auto& s : stems) args.push_back((kScenes / (s + ".toml")).string());
    for (const std::string& a : std::vector<std::string>{"--output-dir", out.string(), "--format", format, "--size", "64x36"})
      args.push_back(a);
    const RunResult r = run_marchstudio(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& s : stems) {
      const fs::path single = dir / (s + "_single." + format);
      render_one(kScenes / (s + ".toml"), single, {"--size", "64x36"});
      expect_same_file(out / (s + "." + format), single);
      EXPECT_NE(r.out.find((out / (s + "." + format)).string()), std::string::npos) << r.out;
    }
  }
}

TEST(Batch, JobKeysOverrideTheCommandLineAndEqualTheSameFlags) {
  TempDir dir;
  // Relative paths start at the job file's directory: the scene is copied there.
  write_file(dir / "seed.toml", read_file(kScenes / "seed.toml"));
  write_file(dir / "seed.glsl", read_file(kScenes / "seed.glsl"));
  write_file(dir / "jobs.jsonl",
             "{\"scene\": \"seed.toml\", \"output\": \"a.png\"}\n"
             "\n"
             "{\"scene\": \"seed.toml\", \"output\": \"b.png\", \"size\": \"40x30\", \"set\": [\"camera.fov=30\"], "
             "\"time\": 0.5, \"spp\": 2}\n"
             "{\"scene\": \"seed.toml\", \"output\": \"c.exr\", \"aov\": \"depth\", \"define\": \"MS_TEST_UNUSED=1\"}\n");
  // Run from the repository root: the job file's paths must not depend on the cwd.
  const RunResult ok =
      run_marchstudio({"render", "--jobs", (dir / "jobs.jsonl").string(), "--size", "48x27"}, source_dir());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  render_one(kScenes / "seed.toml", dir / "a1.png", {"--size", "48x27"});
  render_one(kScenes / "seed.toml", dir / "b1.png",
             {"--size", "40x30", "--set", "camera.fov=30", "--time", "0.5", "--spp", "2"});
  render_one(kScenes / "seed.toml", dir / "c1.exr", {"--size", "48x27", "--aov", "depth", "-D", "MS_TEST_UNUSED=1"});
  // The fingerprint hashes the input file's bytes, not its path: copies match.
  expect_same_file(dir / "a.png", dir / "a1.png");
  expect_same_file(dir / "b.png", dir / "b1.png");
  expect_same_file(dir / "c.exr", dir / "c1.exr");
}

TEST(Batch, OneBadJobFailsAloneAndTheOthersAreWritten) {
  TempDir dir;
  write_file(dir / "seed.toml", read_file(kScenes / "seed.toml"));
  write_file(dir / "seed.glsl", read_file(kScenes / "seed.glsl"));
  write_file(dir / "bad.toml", "[camera]\nfov = \n");
  std::string broken = read_file(kScenes / "seed.toml");
  broken.replace(broken.find("\"seed.glsl\""), 11, "\"broken.glsl\"");
  write_file(dir / "broken.toml", broken);
  write_file(dir / "broken.glsl", "vec2 map(vec3 p) {\n  return vec2(sdSphere(p, 1.0), MAT_BALL) +;\n}\n");
  write_file(dir / "jobs.jsonl",
             "{\"scene\": \"seed.toml\", \"output\": \"good1.png\"}\n"       // 1
             "{\"scene\": \"missing.toml\", \"output\": \"missing.png\"}\n"  // 2
             "{\"scene\": \"bad.toml\", \"output\": \"bad.png\"}\n"          // 3
             "{\"scene\": \"broken.toml\", \"output\": \"broken.png\"}\n"    // 4
             "{\"scene\": \"seed.toml\", \"output\": \"key.png\", \"sizee\": \"8x8\"}\n"  // 5
             "{\"scene\": \"seed.toml\", \"output\": \"json.png\"\n"         // 6
             "{\"scene\": \"seed.toml\", \"output\": \"good2.png\", \"time\": 1}\n");  // 7
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("marchstudio: 5 of 7 jobs failed\n"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "good1.png"));
  EXPECT_TRUE(fs::exists(dir / "good2.png"));
  for (const char* name : {"missing.png", "bad.png", "broken.png", "key.png", "json.png"})
    EXPECT_FALSE(fs::exists(dir / name)) << name;
  // Each bad job's one line names its line of the job file first.
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:2: missing\\.toml: [^\\n]*\\n"))) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:3: bad\\.toml:2: [^\\n]*\\n"))) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:4: [^\\n]*broken\\.glsl:2[^\\n]*\\n")))
      << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:5: unknown key 'sizee' (did you mean 'size'?)\n"), std::string::npos)
      << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:6: not a JSON object[^\\n]*\\n"))) << r.err;
  EXPECT_EQ(count_lines(r.err, "\n"), 6) << r.err;  // five errors and the count, nothing else
  // Nothing but the inputs and the good images: no temporary left behind.
  EXPECT_EQ(dir.entries().size(), 8u);  // 6 inputs, 2 images
}

TEST(Batch, TheWorstExitCodeWinsAndATimedOutJobFailsAlone) {
  TempDir dir;
  const std::string seed = (kScenes / "seed.toml").string();
  write_file(dir / "jobs.jsonl",
             "{\"scene\": \"" + seed + "\", \"output\": \"a.png\"}\n"
             "{\"scene\": \"missing.toml\"}\n"
             // Its programs come from the cache: the render, not a compile, runs out of time.
             "{\"scene\": \"" + seed + "\", \"output\": \"late.png\", \"timeout\": 0.000001}\n"
             // The session goes on after a render cut short: the next image is as a process of its own makes it.
             "{\"scene\": \"" + seed + "\", \"output\": \"after.png\", \"time\": 1}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;  // a system failure (3) over bad input (2)
  EXPECT_NE(r.err.find("marchstudio: 2 of 4 jobs failed\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:3: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--timeout"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  EXPECT_FALSE(fs::exists(dir / "late.png"));
  render_one(seed, dir / "after1.png", {"--size", "32x18", "--time", "1"});
  expect_same_file(dir / "after.png", dir / "after1.png");
}

TEST(Batch, TwoInputsWithOneStemAreRefusedBeforeAnythingRenders) {
  TempDir dir;
  write_file(dir / "other/seed.toml", read_file(kScenes / "seed.toml"));
  write_file(dir / "other/seed.glsl", read_file(kScenes / "seed.glsl"));
  fs::create_directories(dir / "out");
  const RunResult r = run_marchstudio({"render", (kScenes / "columns.toml").string(), (kScenes / "seed.toml").string(),
                                       (dir / "other/seed.toml").string(), "--output-dir", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err, "\n"), 1) << r.err;
  EXPECT_NE(r.err.find("would both write"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir / "out"));  // not even columns.png

  // Several inputs take no -o and no --frames.
  const RunResult o = run_marchstudio(
      {"render", (kScenes / "columns.toml").string(), (kScenes / "seed.toml").string(), "-o", (dir / "x.png").string()});
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_NE(o.err.find("--output-dir"), std::string::npos) << o.err;
  const RunResult f = run_marchstudio({"render", (kScenes / "columns.toml").string(), (kScenes / "seed.toml").string(),
                                       "--output-dir", (dir / "out").string(), "--frames", "0..1"});
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("--frames"), std::string::npos) << f.err;
  EXPECT_TRUE(fs::is_empty(dir / "out"));
}

TEST(Batch, AnIdenticalShaderIsCompiledOnce) {
  TempDir dir;
  const std::string seed = (kScenes / "seed.toml").string();
  // Jobs 1 and 2 assemble the same text (only the output differs); job 3's
  // --disable ao compiles the effect out of its scene pass (its post is the same).
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + seed + "\", \"output\": \"a.png\"}\n" +
                                     "{\"scene\": \"" + seed + "\", \"output\": \"b.png\"}\n" +
                                     "{\"scene\": \"" + seed + "\", \"output\": \"c.png\", \"disable\": \"ao\"}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18", "-v"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> per_job;
  const std::regex line("marchstudio: programs: (\\d+) compiled, (\\d+) from the cache");
  for (std::sregex_iterator it(r.err.begin(), r.err.end(), line), end; it != end; ++it)
    per_job.push_back((*it)[1].str() + "/" + (*it)[2].str());
  EXPECT_EQ(per_job, (std::vector<std::string>{"2/0", "0/2", "1/1"})) << r.err;
  EXPECT_NE(r.err.find("marchstudio: batch: 3 images, 3 programs compiled, 3 from the cache"), std::string::npos)
      << r.err;
  expect_same_file(dir / "a.png", dir / "b.png");  // the reused program draws the same image
}

TEST(Batch, ATerminalGetsABarWithAnEtaAndALogGetsNone) {
  if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "util-linux's script (a pseudo-terminal) is not installed";
  TempDir dir;
  const std::string inputs = (kScenes / "seed.toml").string() + " " + (kScenes / "columns.toml").string();
  const std::string cmd = std::string(MARCH_BIN) + " render " + inputs + " --size 32x18 --output-dir " +
                          dir.path().string();
  // script(1) runs it on a pseudo-terminal: stdout and stderr are a TTY.
  std::string tty;
  if (FILE* p = popen(("/usr/bin/script -qec '" + cmd + "' /dev/null").c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) tty.append(buf, n);
    EXPECT_EQ(pclose(p), 0) << tty;
  }
  EXPECT_NE(tty.find("\r[#"), std::string::npos) << tty;  // redrawn in place
  EXPECT_NE(tty.find("1/2 images"), std::string::npos) << tty;
  EXPECT_NE(tty.find("2/2 images"), std::string::npos) << tty;
  EXPECT_NE(tty.find("ETA"), std::string::npos) << tty;
  // Not a terminal: the paths on stdout and nothing on stderr.
  const RunResult log = run_marchstudio({"render", (kScenes / "seed.toml").string(), (kScenes / "columns.toml").string(),
                                         "--size", "32x18", "--output-dir", dir.path().string()});
  EXPECT_EQ(log.exit_code, 0);
  EXPECT_EQ(log.err, "");
  EXPECT_EQ(count_lines(log.out, "\n"), 2) << log.out;
}
