// --dispatch on every path but the still (the still:
// test_dispatch.cpp): a sequence drawn with compute equals the fragment one
// frame by frame (PNG 1/255, EXR 1e-5, step AOVs equal), also after a
// SIGKILL and a resume; --dispatch auto probes once per device and keeps its
// choice in $XDG_CACHE_HOME/marchstudio/dispatch (counted by its -v lines,
// never by time), rewrites a corrupt cache, and gives an input compute
// cannot run the fragment pass. A --jobs batch takes a `dispatch` key per
// line, and its auto jobs share one probe.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "image_diff.h"
#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

// Enough work per pixel that a frame takes a while on llvmpipe.
const char* kSlow = R"(void mainImage(out vec4 c, in vec2 f) {
  float a = 0.0;
  for (int i = 0; i < 20000; ++i) a += sin(f.x * 0.01 + float(i) * 0.001 + iTime);
  c = vec4(fract(a), fract(iTime), 0.5, 1.0);
}
)";

std::string frame_name(const std::string& prefix, int f, const std::string& ext) {
  return prefix + (f < 10 ? "0" : "") + std::to_string(f) + ext;
}

int count_with(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// The choice field of a one-line dispatch cache.
std::string cached_choice(const std::string& cache) {
  const size_t tab = cache.rfind('\t');
  return tab == std::string::npos ? "" : cache.substr(tab + 1, cache.find('\n', tab) - tab - 1);
}

RunResult run_in(const TempDir& dir, const std::vector<std::string>& args) {
  return run_marchstudio(args, dir.path(), "XDG_CACHE_HOME='" + (dir / "cache").string() + "' ");
}

TEST(DispatchSequence, ComputeEqualsFragmentFrameByFrame) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes" / "seed.toml").string();
  for (const std::string d : {"fragment", "compute"}) {
    for (const std::string ext : {".png", ".exr"}) {
      std::vector<std::string> args = {"render", scene,   "--frames", "0..3", "--fps", "3", "--size", "96x54",
                                       "--spp",  "2",     "--dispatch", d,    "-o",    d.substr(0, 1) + "_%02d" + ext};
      if (ext == ".exr") args.insert(args.end(), {"--aov", "steps,cost"});
      const RunResult r = run_in(dir, args);
      ASSERT_EQ(r.exit_code, 0) << d << ext << ": " << r.err;
    }
  }
  for (int f = 0; f < 4; ++f) {
    const Image fp = read_image(dir / frame_name("f_", f, ".png")), cp = read_image(dir / frame_name("c_", f, ".png"));
    EXPECT_LE(max_diff(fp, cp), 1.0 / 255 + 1e-6) << "frame " << f << " PNG";
    const Image fe = read_image(dir / frame_name("f_", f, ".exr")), ce = read_image(dir / frame_name("c_", f, ".exr"));
    EXPECT_LE(max_diff(fe, ce), 1e-5) << "frame " << f << " EXR";
    EXPECT_FALSE(channel(fe, "steps").empty());
    EXPECT_EQ(channel(fe, "steps"), channel(ce, "steps")) << "frame " << f;
  }
  // Frames differ from one another: the comparison is of an animation.
  EXPECT_GT(max_diff(read_image(dir / "f_00.exr"), read_image(dir / "f_03.exr")), 1e-3);
}

TEST(DispatchSequence, KilledComputeSequenceResumesEqualToFragment) {
  TempDir dir;
  write_file(dir / "slow.glsl", kSlow);
  const std::vector<std::string> args = {"render", "slow.glsl", "--frames", "0..11", "--size",
                                         "160x90", "--dispatch", "compute", "-o",    "k_%02d.png"};
  const pid_t pid = spawn_marchstudio(args, dir.path(), "first.log");
  wait_for_files(dir.path(), "k_", 3, pid, "first.log");
  if (HasFatalFailure()) return;
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const int before = count_files(dir.path(), "k_");
  ASSERT_LT(before, 12) << "killed halfway, not at the end";

  const RunResult r = run_marchstudio(args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_with(r.err, " skipped: "), before) << r.err;
  EXPECT_EQ(count_with(r.err, " rendered in "), 12 - before) << r.err;
  const RunResult f = run_marchstudio({"render", "slow.glsl", "--frames", "0..11", "--size", "160x90", "-o",
                                       "f_%02d.png"},
                                      dir.path());
  ASSERT_EQ(f.exit_code, 0) << f.err;
  for (int n = 0; n < 12; ++n)
    EXPECT_LE(max_diff(read_image(dir / frame_name("f_", n, ".png")), read_image(dir / frame_name("k_", n, ".png"))),
              1.0 / 255 + 1e-6)
        << "frame " << n;
}

TEST(DispatchSequence, RefusesWhatComputeCannotRunInOneLine) {
  TempDir dir;
  write_file(dir / "d.glsl", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(dFdx(f.x));\n}\n");
  const RunResult r = run_in(dir, {"render", "d.glsl", "--frames", "0..2", "--size", "16x16", "--dispatch",
                                   "compute", "-o", "x_%02d.png"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("d.glsl:2"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(count_files(dir.path(), "x_"), 0);
}

TEST(DispatchAuto, ProbesOnceThenReadsTheCache) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes" / "seed.toml").string();
  const auto run = [&](const std::string& out, const std::string& dispatch) {
    const RunResult r = run_in(dir, {"render", scene, "--size", "96x54", "--dispatch", dispatch, "-v", "-o", out});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.err;
  };
  const std::string first = run("a1.exr", "auto");
  EXPECT_EQ(count_with(first, "dispatch auto: probe: "), 1) << first;
  const fs::path cache = dir / "cache" / "marchstudio" / "dispatch";
  ASSERT_TRUE(fs::exists(cache));
  const std::string kept = read_file(cache);
  EXPECT_EQ(count_with(kept, "\n"), 1) << kept;
  const std::string choice = cached_choice(kept);  // "fragment" or "compute WxH"
  EXPECT_TRUE(choice == "fragment" || choice.rfind("compute ", 0) == 0) << kept;
  const std::string second = run("a2.exr", "auto");
  EXPECT_EQ(count_with(second, "dispatch auto: probe: "), 0) << second;
  EXPECT_NE(second.find("dispatch auto: " + choice + " (cached for "), std::string::npos) << second;
  EXPECT_EQ(read_file(cache), kept);
  // Whichever it chose, the image is the fragment pass's.
  run("f.exr", "fragment");
  EXPECT_LE(max_diff(read_image(dir / "a2.exr"), read_image(dir / "f.exr")), 1e-5);
  EXPECT_LE(max_diff(read_image(dir / "a1.exr"), read_image(dir / "f.exr")), 1e-5);
  // A sequence reads the same cache.
  const RunResult seq = run_in(dir, {"render", scene, "--frames", "0..1", "--size", "32x18", "--dispatch", "auto",
                                     "-v", "-o", "s_%02d.png"});
  ASSERT_EQ(seq.exit_code, 0) << seq.err;
  EXPECT_EQ(count_with(seq.err, "dispatch auto: probe: "), 0) << seq.err;
  EXPECT_NE(seq.err.find("dispatch auto: " + choice + " (cached for "), std::string::npos) << seq.err;
}

TEST(DispatchAuto, ACorruptCacheIsIgnoredAndRewritten) {
  TempDir dir;
  const fs::path cache = dir / "cache" / "marchstudio" / "dispatch";
  fs::create_directories(cache.parent_path());
  write_file(cache, "not\ta cache line\n\x01\x02 garbage");
  const std::string scene = (source_dir() / "scenes" / "seed.toml").string();
  const RunResult r = run_in(dir, {"render", scene, "--size", "32x18", "--dispatch", "auto", "-v", "-o", "a.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("is unreadable: ignored"), std::string::npos) << r.err;
  EXPECT_EQ(count_with(r.err, "dispatch auto: probe: "), 1) << r.err;
  const std::string kept = read_file(cache);
  EXPECT_EQ(count_with(kept, "\n"), 1) << kept;
  EXPECT_TRUE(kept.find("\tfragment\n") != std::string::npos || kept.find("\tcompute ") != std::string::npos) << kept;
  const RunResult again = run_in(dir, {"render", scene, "--size", "32x18", "--dispatch", "auto", "-v", "-o", "b.png"});
  EXPECT_EQ(count_with(again.err, "dispatch auto: probe: "), 0) << again.err;
}

// The cache's group is what compute draws with ("compute" alone: 8x8, the
// format before groups were measured), a given --compute-group overrides
// it, and a group that cannot be makes the cache unreadable.
TEST(DispatchAuto, TheCachedGroupIsWhatComputeDrawsWith) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes" / "seed.toml").string();
  const auto run = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", scene, "--size", "96x54", "-v", "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_in(dir, args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.err;
  };
  run("f.exr", {"--dispatch", "fragment"});
  run("probe.png", {"--dispatch", "auto"});
  const fs::path cache = dir / "cache" / "marchstudio" / "dispatch";
  const std::string line = read_file(cache);
  const std::string device = line.substr(0, line.rfind('\t') + 1);  // GL_RENDERER, GL_VERSION
  const Image f = read_image(dir / "f.exr");
  const struct {
    std::string cached;
    std::vector<std::string> extra;
    std::string said;
  } cases[] = {{"compute 16x16", {}, "compute 16x16"},
               {"compute", {}, "compute 8x8"},
               {"compute 16x8/4", {}, "compute 16x8/4"},
               {"compute 16x16", {"--compute-group", "32x4"}, "compute 32x4"},
               {"fragment", {}, "fragment"}};
  for (const auto& c : cases) {
    write_file(cache, device + c.cached + "\n");
    std::vector<std::string> extra = {"--dispatch", "auto"};
    extra.insert(extra.end(), c.extra.begin(), c.extra.end());
    const std::string err = run("a.exr", extra);
    EXPECT_NE(err.find("dispatch auto: " + c.said + " (cached for "), std::string::npos) << c.cached << "\n" << err;
    EXPECT_LE(max_diff(f, read_image(dir / "a.exr")), 1e-5) << c.cached;
  }
  write_file(cache, device + "compute 64x64\n");  // 4096 invocations: no such group
  const std::string err = run("b.png", {"--dispatch", "auto"});
  EXPECT_NE(err.find("is unreadable: ignored"), std::string::npos) << err;
  EXPECT_EQ(count_with(err, "dispatch auto: probe: "), 1) << err;
}

TEST(DispatchAuto, AnInputComputeCannotRunGetsTheFragmentPass) {
  TempDir dir;
  write_file(dir / "d.glsl", "void mainImage(out vec4 c, in vec2 f) {\n  c = vec4(fwidth(f.x), 0.5, 0.0, 1.0);\n}\n");
  const RunResult r = run_in(dir, {"render", "d.glsl", "--size", "16x16", "--dispatch", "auto", "-v", "-o", "a.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("dispatch auto: fragment (this input cannot run as compute: "), std::string::npos) << r.err;
  EXPECT_EQ(count_with(r.err, "probe: "), 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "cache" / "marchstudio" / "dispatch")) << "no probe, nothing cached";
  const RunResult f = run_in(dir, {"render", "d.glsl", "--size", "16x16", "-o", "f.png"});
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(max_diff(read_image(dir / "a.png"), read_image(dir / "f.png")), 0.0);
}

TEST(DispatchBatch, JobLinesChooseTheirDispatchAndShareOneProbe) {
  TempDir dir;
  const std::string scene = (source_dir() / "scenes" / "stilllife.toml").string();
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + scene + "\", \"output\": \"f.exr\"}\n"
                                 "{\"scene\": \"" + scene + "\", \"output\": \"c.exr\", \"dispatch\": \"compute\"}\n"
                                 "{\"scene\": \"" + scene + "\", \"output\": \"a1.exr\", \"dispatch\": \"auto\"}\n"
                                 "{\"scene\": \"" + scene + "\", \"output\": \"a2.exr\", \"dispatch\": \"auto\"}\n");
  const RunResult r = run_in(dir, {"render", "--jobs", "jobs.jsonl", "--size", "64x36", "--spp", "2", "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_with(r.err, "dispatch auto: probe: "), 1) << r.err;
  EXPECT_EQ(count_with(r.err, " (cached for "), 1) << r.err;
  const Image f = read_image(dir / "f.exr");
  for (const char* name : {"c.exr", "a1.exr", "a2.exr"}) EXPECT_LE(max_diff(f, read_image(dir / name)), 1e-5) << name;
  write_file(dir / "bad.jsonl", "{\"scene\": \"" + scene + "\", \"output\": \"x.png\", \"dispatch\": \"gpu\"}\n");
  const RunResult refused = run_in(dir, {"render", "--jobs", "bad.jsonl"});
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("'gpu' is not one of fragment, compute, auto"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
}  // namespace ms::test
