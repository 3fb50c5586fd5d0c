// `marchstudio view` under Xvfb (a real GLFW window on Mesa llvmpipe): hot
// reload on rename-saves, compile errors that keep the last good frame and
// name file:line, recovery, new includes watched and removed ones dropped,
// reload latency counted in frames, and every debug view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "io/image_io.h"
#include "render/aov.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// The seed scene's map with the ball in the floor's material; the tests
// turn it red (MAT_BALL), break it, fix it, grow it from an include.
std::string map_glsl(const std::string& ball_mat, const std::string& radius = "1.0",
                     const std::string& include = "") {
  return include +
         "// viewer test map\n"
         "vec2 map(vec3 p) {\n"
         "  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_FLOOR);\n"
         "  vec2 ball = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), " + radius + "), " + ball_mat + ");\n"
         "  return opUnion(ground, ball);\n"
         "}\n";
}

constexpr int kMaxLatencyFrames = 3;

class Viewer : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!on_path("Xvfb")) GTEST_SKIP() << "Xvfb is not on PATH (Debian: apt install xvfb)";
    // map = "seed.glsl", next to it. Without [bounds]: the tests grow the
    // ball, which a tight bounding volume would clip.
    write_file(dir / "seed.toml", toml);
    write_file(dir / "seed.glsl", map_glsl("MAT_FLOOR"));
  }

  void start(std::vector<std::string> extra = {}) {
    std::vector<std::string> argv = {"env", x_display(), MARCH_BIN, "view",
                                     (dir / "seed.toml").string(), "--size", "160x90", "--paused", "--no-panel",
                                     "--log", log().string(), "--capture-dir", (dir / "cap").string(),
                                     "--exit-after", "55"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    proc = std::make_unique<BackgroundProcess>(argv, dir / "out.txt", dir / "err.txt");
    ASSERT_TRUE(proc->started());
    const std::string first = wait_for_line(log(), "^reload (ok|failed) 0 ", 30);
    ASSERT_FALSE(first.empty()) << read_file(dir / "err.txt");
    ASSERT_FALSE(wait_for_line(log(), "^capture 0 ", 10).empty());
  }

  fs::path log() const { return dir / "log.txt"; }
  // scenes/seed.toml without its [bounds] table.
  const std::string toml = [] {
    std::string t = read_file(source_dir() / "scenes/seed.toml");
    const size_t at = t.find("\n[bounds]\n");
    if (at != std::string::npos) t.erase(at + 1, t.find("\n[", at + 1) - at);
    return t;
  }();
  Image capture(int k) { return read_image(dir / "cap" / ("frame_" + std::to_string(k) + ".png")); }

  // Saves by rename, waits for reload number `k`, checks its latency and
  // returns its log line.
  std::string save_and_wait(const fs::path& file, const std::string& text, int k) {
    const auto t0 = std::chrono::steady_clock::now();
    save_by_rename(file, text);
    const std::string line = wait_for_line(log(), "^reload (ok|failed) " + std::to_string(k) + " ", 20);
    const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_FALSE(line.empty()) << "no reload " << k << "\n" << read_file(log()) << read_file(dir / "err.txt");
    if (line.empty()) return line;
    EXPECT_GE(field(line, "frames"), 1);
    // Frames drawn with the old program while the worker compiled do not
    // count (live/compile_worker.h): once ready, the new one shows at once.
    EXPECT_GE(field(line, "frames_during_compile"), 0.0) << line;
    EXPECT_LE(field(line, "frames") - field(line, "frames_during_compile"), kMaxLatencyFrames) << line;
    // The split of its time (docs/viewer.md): ours and the driver's within the total, the first draw timed.
    EXPECT_GE(field(line, "assemble_ms"), 0.0) << line;
    EXPECT_GE(field(line, "gl_ms"), 0.0) << line;
    EXPECT_LE(field(line, "assemble_ms") + field(line, "gl_ms"), field(line, "compile_ms") + 0.2) << line;
    EXPECT_GT(field(line, "first_draw_ms"), 0.0) << line;
    EXPECT_FALSE(wait_for_line(log(), "^capture " + std::to_string(k) + " ", 10).empty());
    // For docs/viewer.md: save -> log line, as a person would see it.
    std::cout << "[ latency ] reload " << k << ": " << wall_ms << " ms from the rename to the log line; " << line
              << "\n";
    return line;
  }

  int frames_logged() {
    int n = -1;
    for (const std::string& l : file_lines(log()))
      if (l.rfind("frames ", 0) == 0) n = std::stoi(l.substr(7));
    return n;
  }

  TempDir dir;
  std::unique_ptr<BackgroundProcess> proc;
};

TEST_F(Viewer, EditBreakFixRecover) {
  start();
  const Image grey = capture(0);

  // 1. A colour change in the GLSL, saved by rename: the ball turns red.
  std::string line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL"), 1);
  ASSERT_EQ(line.rfind("reload ok 1", 0), 0u) << line;
  const Image red = capture(1);
  EXPECT_GT(redness(red), redness(grey) + 0.02) << "the frame did not get redder";

  // 2. A syntax error: still running, file:line reported, frames still come,
  //    and the frame shown is the last good one.
  const int frames_before = frames_logged();
  line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BAL"), 2);  // undeclared identifier on line 4
  ASSERT_EQ(line.rfind("reload failed 2", 0), 0u) << line;
  EXPECT_NE(line.find("seed.glsl:4:"), std::string::npos) << line;
  EXPECT_NE(read_file(dir / "err.txt").find("seed.glsl:4:"), std::string::npos);  // and on the console
  EXPECT_TRUE(proc->running());
  EXPECT_TRUE(wait_until([&] { return frames_logged() > std::max(frames_before, 0) + 1; }, 10))
      << "frames stopped coming after the error";
  EXPECT_LT(mean_abs_diff(capture(2), red), 1e-3) << "the last good frame is not what is shown";

  // 3. Fixed: recovers (a different colour proves it is the new program).
  line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL", "1.2"), 3);
  ASSERT_EQ(line.rfind("reload ok 3", 0), 0u) << line;
  EXPECT_GT(redness(capture(3)), redness(red) + 0.005) << "a bigger red ball should be redder";
  EXPECT_TRUE(proc->running());
  // The viewer never writes the scene file unless asked (C, Ctrl+S).
  EXPECT_EQ(read_file(dir / "seed.toml"), toml);
}

TEST_F(Viewer, NewIncludeIsWatchedAndRemovedOneIsNot) {
  start();
  write_file(dir / "radius.glsl", "float ballRadius() { return 0.8; }\n");
  // 4. A new #include of a new file...
  std::string line =
      save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL", "ballRadius()", "#include \"radius.glsl\"\n"), 1);
  ASSERT_EQ(line.rfind("reload ok 1", 0), 0u) << line;
  const Image small = capture(1);
  // ...then an edit of that file alone reloads.
  line = save_and_wait(dir / "radius.glsl", "float ballRadius() { return 1.3; }\n", 2);
  ASSERT_EQ(line.rfind("reload ok 2", 0), 0u) << line;
  EXPECT_GT(redness(capture(2)), redness(small) + 0.01);

  // Drop the include: the file is no longer watched.
  line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL"), 3);
  ASSERT_EQ(line.rfind("reload ok 3", 0), 0u) << line;
  save_by_rename(dir / "radius.glsl", "float ballRadius() { return 0.5; }\n");
  EXPECT_TRUE(wait_for_line(log(), "^reload (ok|failed) 4 ", 1.5).empty()) << "an unused file triggered a reload";
}

TEST_F(Viewer, BrokenAtStartThenDeletedThenRecreated) {
  write_file(dir / "seed.glsl", map_glsl("MAT_NOPE"));
  start();
  EXPECT_FALSE(wait_for_line(log(), "^reload failed 0 .*seed.glsl:4:", 1).empty()) << read_file(log());
  EXPECT_TRUE(proc->running());
  // Fixed: the first good program.
  std::string line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL"), 1);
  ASSERT_EQ(line.rfind("reload ok 1", 0), 0u) << line;
  // Deleted: an error, still running; recreated: back.
  fs::remove(dir / "seed.glsl");
  ASSERT_FALSE(wait_for_line(log(), "^reload failed 2 ", 20).empty()) << read_file(log());
  EXPECT_TRUE(proc->running());
  line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_BALL"), 3);
  EXPECT_EQ(line.rfind("reload ok 3", 0), 0u) << line;
  // A half-written file (truncated mid-save) then the full one.
  { std::ofstream(dir / "seed.glsl") << "vec2 map(vec3 p) {\n  vec2 ground = "; }
  ASSERT_FALSE(wait_for_line(log(), "^reload failed 4 ", 20).empty()) << read_file(log());
  line = save_and_wait(dir / "seed.glsl", map_glsl("MAT_FLOOR"), 5);
  EXPECT_EQ(line.rfind("reload ok 5", 0), 0u) << line;
  EXPECT_TRUE(proc->running());
}

TEST_F(Viewer, ScreenshotsAtWindowAndChosenSize) {
  start({"--shot-frame", "2", "--shot-size", "200x120", "--shot-dir", (dir / "shots").string()});
  ASSERT_FALSE(wait_for_line(log(), "^screenshot ", 20).empty()) << read_file(log());
  const Image shot = read_image(dir / "shots/seed_1.png");
  EXPECT_EQ(shot.width, 200);
  EXPECT_EQ(shot.height, 120);
  ASSERT_FALSE(wait_for_line(log(), "^window_shot ", 5).empty());
  const Image window = read_image(dir / "shots/seed_window_1.png");
  EXPECT_EQ(window.width, 160);
  EXPECT_EQ(window.height, 90);
}

// --set and --uniform (docs/usage.md#overrides) hold from the first frame
// and across reloads: a save of the scene or the map keeps them.
TEST_F(Viewer, OverridesHoldAcrossReloads) {
  const std::string map =
      "uniform float uR = 1.0; // range(0.5, 2.0)\n"
      "vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), uR), MAT_BALL); }\n";
  write_file(dir / "seed.glsl", map);
  const std::vector<std::string> overrides = {"--set", "materials.floor.color=[0.1,0.2,0.9]", "--uniform", "uR=1.4"};
  start(overrides);
  const Image first = capture(0);
  // `render` of the same scene with and without them, for what "held" means.
  auto render = [&](const std::string& out, std::vector<std::string> more) {
    std::vector<std::string> args = {"render", (dir / "seed.toml").string(), "--size", "160x90", "-o",
                                     (dir / out).string()};
    args.insert(args.end(), more.begin(), more.end());
    EXPECT_EQ(run_marchstudio(args).exit_code, 0);
    return read_image(dir / out);
  };
  const Image with = render("with.png", overrides), without = render("without.png", {});
  // The viewer shows what `render` writes (0 here on llvmpipe), and they change it.
  EXPECT_LT(mean_abs_diff(first, with), 1e-3) << "the first frame is not render's with the overrides";
  EXPECT_GT(mean_abs_diff(first, without), 0.02) << "the overrides changed nothing";

  ASSERT_EQ(save_and_wait(dir / "seed.toml", toml, 1).rfind("reload ok 1", 0), 0u);
  ASSERT_EQ(save_and_wait(dir / "seed.glsl", "// saved again\n" + map, 2).rfind("reload ok 2", 0), 0u);
  EXPECT_LT(mean_abs_diff(capture(1), first), 1e-3) << "a save of the scene dropped them";
  EXPECT_LT(mean_abs_diff(capture(2), first), 1e-3) << "a save of the map dropped them";
}

// A failed build shows the whole compiler log, not just "+N more" (issue
// 17 item 7): the event log carries it as compile_log lines, each mapped to
// the map file's line, and the panel's error window shows the same text.
TEST_F(Viewer, FailedBuildCarriesTheWholeLog) {
  start();
  const std::string broken =
      "vec2 map(vec3 p) {\n"
      "  float a = undefinedOne(p);\n"
      "  float b = undefinedTwo(p);\n"
      "  return vec2(a + b, MAT_FLOOR);\n"
      "}\n";
  save_by_rename(dir / "seed.glsl", broken);
  const std::string line = wait_for_line(log(), "^reload failed 1 ", 20);
  ASSERT_FALSE(line.empty()) << read_file(log());
  EXPECT_NE(line.find("more"), std::string::npos) << "two errors should give a '+N more' hint: " << line;
  // The log follows, here as in the red box: the hint says so, not "-v".
  EXPECT_NE(line.find("the full log is below"), std::string::npos) << line;
  EXPECT_EQ(line.find("-v prints"), std::string::npos) << line;
  const std::string map = (dir / "seed.glsl").string();
  bool one = false, two = false;
  for (const std::string& l : file_lines(log())) {
    if (l.rfind("compile_log ", 0) != 0) continue;
    one = one || (l.find(map + ":2:") != std::string::npos && l.find("undefinedOne") != std::string::npos);
    two = two || (l.find(map + ":3:") != std::string::npos && l.find("undefinedTwo") != std::string::npos);
  }
  EXPECT_TRUE(one && two) << read_file(log());
}

// One home for presets: `view --preset NAME` starts from the
// same values as `render --preset NAME`, textbook included, so its first
// frame is render's image at that preset.
TEST_F(Viewer, PresetsAreRendersPresets) {
  auto render = [&](const std::string& preset) {
    const fs::path out = dir / ("render_" + preset + ".png");
    EXPECT_EQ(run_marchstudio({"render", (dir / "seed.toml").string(), "--size", "160x90", "--preset", preset, "-o",
                               out.string()})
                  .exit_code,
              0);
    return read_image(out);
  };
  const Image balanced = render("balanced");
  double moved = 0;  // how far some preset moves render's image: the test can see a preset ignored
  for (const std::string preset : {"fast", "balanced", "reference", "textbook"}) {
    proc.reset();
    fs::remove(log());
    fs::remove_all(dir / "cap");
    start({"--preset", preset});
    const Image want = render(preset), got = capture(0);
    EXPECT_LE(max_abs_diff(got, want), 1.0 / 255.0) << preset << ": the viewer's frame is not render's";
    moved = std::max(moved, max_abs_diff(want, balanced));
  }
  EXPECT_GT(moved, 2.0 / 255.0) << "no preset changed render's image of the seed scene";
}

// Debug views show values: normals as 0.5 N + 0.5, depth as the legend's
// grey, AO as itself, stored without exposure, tone map or sRGB encode.
// Checked against render --aov of the same frame, where rays hit.
TEST_F(Viewer, DebugViewsShowValuesNotRadiance) {
  write_file(dir / "seed.glsl", map_glsl("MAT_BALL"));
  write_file(dir / "seed.toml", toml + "\n[quality]\nmax_distance = 40.0\n");
  const fs::path aov = dir / "aov.exr";
  const RunResult r = run_marchstudio({"render", (dir / "seed.toml").string(), "--size", "160x90", "--aov",
                                       "normal,depth,ao", "-o", aov.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image a = read_image(aov);
  auto channel = [&](const std::string& name) {
    const auto it = std::find(a.channels.begin(), a.channels.end(), name);
    EXPECT_NE(it, a.channels.end()) << name;
    return static_cast<int>(it - a.channels.begin());
  };
  const int hit = channel("hit"), z = channel("Z"), nx = channel("N.x"), ao = channel("ao");
  for (const int view : {2, 3, 4}) {
    proc.reset();
    fs::remove(log());
    fs::remove_all(dir / "cap");
    start({"--debug-view", std::to_string(view), "--max-frames", "2"});
    const Image got = capture(0);
    ASSERT_EQ(got.width, a.width);
    int compared = 0, off = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        if (a.at(x, y, hit) != 1.0f) continue;  // misses are black; edges mix samples
        for (int c = 0; c < 3; ++c) {
          const float want = view == 2   ? 0.5f * a.at(x, y, nx + c) + 0.5f
                             : view == 3 ? depth_shade(a.at(x, y, z), 40.0f)
                                         : a.at(x, y, ao);
          off += std::abs(got.at(x, y, c) - want) > 1.0f / 255.0f;
          ++compared;
        }
      }
    EXPECT_GT(compared, 3 * 160 * 90 / 4) << "view " << view;
    EXPECT_LE(off, compared / 1000) << "debug view " << view << " does not show the AOV's values";
  }
}

// Progressive accumulation: paused, each frame adds one of render --spp N's
// samples; the converged frame is render --spp N's image, and a reload
// starts again from one sample.
TEST_F(Viewer, AccumulationConvergesToRenderSpp) {
  write_file(dir / "seed.glsl", map_glsl("MAT_BALL"));
  start({"--accumulate", "4", "--max-frames", "40"});
  ASSERT_FALSE(wait_for_line(log(), "^converged 4$", 30).empty()) << read_file(log());
  ASSERT_FALSE(wait_for_line(log(), "^accumulated_shot 4 ", 10).empty()) << read_file(log());
  auto render = [&](const std::string& spp, const std::string& name) {
    const fs::path out = dir / name;
    const RunResult r = run_marchstudio({"render", (dir / "seed.toml").string(), "--size", "160x90", "--spp", spp,
                                         "-o", out.string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_image(out);
  };
  const Image converged = read_image(dir / "cap" / "converged_4.png");
  const Image want = render("4", "spp4.png");
  EXPECT_LE(max_abs_diff(converged, want), 1.0 / 255.0) << "the converged frame is not render --spp 4";
  // The first frame is one of those samples alone (jittered: not render --spp 1's pixel centres).
  EXPECT_GT(max_abs_diff(capture(0), want), 8.0 / 255.0) << "one sample looks like 4: the test cannot see accumulation";
  // A reload restarts it: converged again, to the new map's image.
  proc.reset();
  fs::remove(log());
  fs::remove_all(dir / "cap");
  start({"--accumulate", "4"});
  ASSERT_FALSE(wait_for_line(log(), "^converged 4$", 30).empty()) << read_file(log());
  save_by_rename(dir / "seed.glsl", map_glsl("MAT_BALL", "0.8"));
  ASSERT_FALSE(wait_for_line(log(), "^reload ok 1 ", 20).empty()) << read_file(log());
  auto converged_lines = [&] {
    const std::vector<std::string> l = file_lines(log());
    return std::count(l.begin(), l.end(), std::string("converged 4"));
  };
  for (int i = 0; i < 200 && converged_lines() < 2; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::vector<std::string> all = file_lines(log());
  EXPECT_EQ(std::count(all.begin(), all.end(), std::string("converged 4")), 2) << read_file(log());
}

// Recording: --record A..B writes frames at exactly f / fps through the
// screenshot path, so they equal render --frames A..B of an animated map,
// whatever the window's own clock did.
TEST_F(Viewer, RecordingEqualsRenderFrames) {
  write_file(dir / "seed.glsl", map_glsl("MAT_BALL", "(0.7 + 0.3 * sin(uTime * 6.0))"));
  start({"--record", "2..6", "--record-fps", "12", "--record-dir", (dir / "rec").string()});
  ASSERT_FALSE(wait_for_line(log(), "^record done 5 frames ", 60).empty()) << read_file(log());
  const RunResult r = run_marchstudio({"render", (dir / "seed.toml").string(), "--size", "160x90", "--frames", "2..6",
                                       "--fps", "12", "-o", (dir / "want" / "frame_%04d.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"frame_0002.png", "frame_0003.png", "frame_0004.png", "frame_0005.png", "frame_0006.png"})
    EXPECT_LE(max_abs_diff(read_image(dir / "rec" / f), read_image(dir / "want" / f)), 1.0 / 255.0) << f;
  EXPECT_FALSE(fs::exists(dir / "rec" / "frame_0001.png"));
  EXPECT_FALSE(fs::exists(dir / "rec" / "frame_0007.png"));
  EXPECT_GT(max_abs_diff(read_image(dir / "want" / "frame_0002.png"), read_image(dir / "want" / "frame_0004.png")),
            8.0 / 255.0)
      << "the frames do not move: the test cannot tell times apart";
}

class DebugView : public Viewer, public ::testing::WithParamInterface<int> {};

// Each debug view compiles, renders and differs from the lit image.
TEST_P(DebugView, RendersAndDiffersFromLit) {
  write_file(dir / "seed.glsl", map_glsl("MAT_BALL"));
  start({"--debug-view", "0", "--max-frames", "2"});
  const Image lit = capture(0);
  proc.reset();
  fs::remove_all(dir / "cap");
  fs::remove(log());
  start({"--debug-view", std::to_string(GetParam()), "--max-frames", "2"});
  EXPECT_FALSE(wait_for_line(log(), "^reload ok 0 ", 1).empty()) << read_file(log());
  const Image view = capture(0);
  EXPECT_GT(mean_abs_diff(view, lit), 0.03) << "debug view " << GetParam() << " looks like the lit image";
}

INSTANTIATE_TEST_SUITE_P(Views, DebugView, ::testing::Range(1, 7));

}  // namespace
}  // namespace ms::test
