// Huge stills (docs/usage.md#huge-stills) through the real
// binary, at small sizes with tiling forced by the hidden --tile-still: a
// tiled still is bit-identical to a whole one (PNG and EXR, 1 and several
// samples, AOVs, a Shadertoy shader reading gl_FragCoord and derivatives),
// carries the same fingerprint, counts NaN/Inf pixels the same (--strict
// leaves no file), leaves nothing on a full disk, SIGTERM (also right after the
// temporary is made) or --timeout, refuses a
// shader with buffers, and draws a progress bar on a terminal.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "dispatch.h"
#include "io/image_io.h"
#include "run.h"
#include "test_viewer_util.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kSeed = (source_dir() / "scenes/seed.toml").string();

// fragCoord, gl_FragCoord, iResolution and screen-space derivatives (taken
// over 2x2 quads): each would show a tile's seam if a tile saw its own
// coordinates or a quad straddled two tiles.
const char* kCoords =
    "void mainImage(out vec4 c, in vec2 f) {\n"
    "  vec2 uv = f / iResolution.xy;\n"
    "  float w = fwidth(sin(f.x * f.y * 0.013));\n"
    "  c = vec4(fract(uv * 7.3), fract(gl_FragCoord.x * 0.37 + gl_FragCoord.y * 0.11) + w + dFdy(uv.x * uv.y * 40.0),"
    " 1.0);\n"
    "}\n";

bool one_line(const std::string& err) {
  return !err.empty() && std::count(err.begin(), err.end(), '\n') == 1 && err.back() == '\n';
}

RunResult render(const std::string& input, const fs::path& out, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render", input, "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_marchstudio(args);
}

// Renders whole and tiled (each `sides` of --tile-still) and expects the
// same pixels, channels and fingerprint.
void expect_tiled_identical(const std::string& input, const std::string& ext, const std::vector<std::string>& extra,
                            const std::vector<std::string>& sides) {
  TempDir dir;
  const RunResult whole = render(input, dir / ("whole." + ext), extra);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const Image ref = read_image(dir / ("whole." + ext));
  const std::string fingerprint = read_image_info(dir / ("whole." + ext)).fingerprint;
  ASSERT_FALSE(fingerprint.empty());
  for (const std::string& side : sides) {
    const fs::path out = dir / ("tiled" + side + "." + ext);
    std::vector<std::string> args = extra;
    args.insert(args.end(), {"--tile-still", side});
    const RunResult r = render(input, out, args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image tiled = read_image(out);
    EXPECT_EQ(tiled.width, ref.width);
    EXPECT_EQ(tiled.height, ref.height);
    EXPECT_EQ(tiled.channels, ref.channels);
    EXPECT_TRUE(tiled.pixels == ref.pixels) << input << " " << ext << " tiles of " << side;
    EXPECT_EQ(read_image_info(out).fingerprint, fingerprint) << "the tiling is not part of what made the image";
  }
}

// 301x203: odd sides, so the last column and the top band are partial;
// 64 gives 5 x 4 tiles, 50 gives 7 x 5 (of 44 columns, then the rest).
// A scene's tiles hold for either dispatch of its pass.
class HugeStillScene : public BothDispatches {};

TEST_P(HugeStillScene, ATiledSceneIsBitIdenticalAsPngAtOneSample) {
  expect_tiled_identical(kSeed, "png", with_dispatch({"--size", "301x203", "--spp", "1"}), {"64", "50"});
}

TEST_P(HugeStillScene, ATiledSceneIsBitIdenticalAsExrWithSamplesAndAovs) {
  expect_tiled_identical(kSeed, "exr",
                         with_dispatch({"--size", "301x203", "--spp", "3", "--aov", "depth,normal,steps,cost"}), {"64"});
  expect_tiled_identical(kSeed, "exr", with_dispatch({"--size", "301x203", "--spp", "1"}), {"50"});
}

INSTANTIATE_BOTH_DISPATCHES(HugeStillScene);

TEST(HugeStill, ATiledShadertoyShaderIsBitIdentical) {
  TempDir src;
  write_file(src / "coords.glsl", kCoords);
  const std::string shader = (src / "coords.glsl").string();
  expect_tiled_identical(shader, "png", {"--size", "301x203"}, {"64", "50"});
  expect_tiled_identical(shader, "exr", {"--size", "301x203", "--spp", "4"}, {"64"});
}

// A NaN in every pixel of the rows above 150 (of 203): split across bands.
const char* kNanRows =
    "void mainImage(out vec4 c, in vec2 f) {\n"
    "  c = vec4(f.y > 150.0 ? sqrt(-1.0 - f.x) : 0.5, 0.5, 0.5, 1.0);\n"
    "}\n";

TEST(HugeStill, NanPixelsAreCountedOverTheBandsAndStrictLeavesNoFile) {
  TempDir dir;
  write_file(dir / "nan.glsl", kNanRows);
  const std::string shader = (dir / "nan.glsl").string();
  const RunResult whole = render(shader, dir / "whole.png", {"--size", "301x203"});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const size_t at = whole.err.find(" pixels have NaN/Inf values");
  ASSERT_NE(at, std::string::npos) << whole.err;
  const std::string whole_count = whole.err.substr(whole.err.rfind(": ", at) + 2, at - whole.err.rfind(": ", at) - 2);
  EXPECT_EQ(whole_count, "15953 of 61103");  // fragCoord.y = row + 0.5 > 150: rows 150..202, 53 of 301 pixels
  const RunResult tiled = render(shader, dir / "tiled.png", {"--size", "301x203", "--tile-still", "64"});
  ASSERT_EQ(tiled.exit_code, 0) << tiled.err;
  EXPECT_NE(tiled.err.find(whole_count + " pixels have NaN/Inf values"), std::string::npos) << tiled.err;
  EXPECT_TRUE(read_image(dir / "tiled.png").pixels == read_image(dir / "whole.png").pixels);

  const RunResult strict = render(shader, dir / "strict.png", {"--size", "301x203", "--tile-still", "64", "--strict"});
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  EXPECT_TRUE(one_line(strict.err)) << strict.err;
  EXPECT_NE(strict.err.find("--strict: " + whole_count + " pixels have NaN/Inf values; nothing written"),
            std::string::npos)
      << strict.err;
  std::vector<std::string> left = dir.entries();
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"nan.glsl", "tiled.png", "whole.png"})) << "no file, no temporary";
}

TEST(HugeStill, AFullDiskLeavesNoFileAndNoTemporary) {
  TempDir dir;
  // 32 KiB: the first bands fit, a later one does not.
  const RunResult r = run_marchstudio({"render", kSeed, "--size", "640x360", "--tile-still", "64", "-o", "out.png"},
                                      dir.path(), "ulimit -f 32; ");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("out.png: cannot write the file: File too large; nothing was written"), std::string::npos)
      << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

// A tiled 2048x2048 EXR render (about 10 s of bands on llvmpipe), sent
// SIGTERM as soon as its temporary appears: exit 143, and nothing left but
// the logs. `env` (NAME=VALUE) goes on the binary's command line through env(1).
void expect_sigterm_leaves_nothing(const std::vector<std::string>& env) {
  TempDir dir;
  std::vector<std::string> argv;
  if (!env.empty()) {
    argv.push_back("env");
    argv.insert(argv.end(), env.begin(), env.end());
  }
  for (const char* a : {MARCH_BIN, "render", kSeed.c_str(), "--size", "2048x2048", "--spp", "8", "--tile-still", "256",
                        "-o", "big.exr"})
    argv.emplace_back(a);
  BackgroundProcess p(argv, dir / "out.txt", dir / "err.txt", dir.path());
  const auto temp_exists = [&] {
    for (const std::string& name : dir.entries())
      if (name.rfind(".big.exr.tmp", 0) == 0) return true;
    return false;
  };
  ASSERT_TRUE(wait_until(temp_exists, 60)) << read_file(dir / "err.txt");
  p.signal(SIGTERM);
  EXPECT_EQ(p.wait_exit(30), 128 + SIGTERM) << read_file(dir / "err.txt");
  std::vector<std::string> left = dir.entries();
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"err.txt", "out.txt"}));
}

TEST(HugeStill, SigtermRemovesTheTemporary) { expect_sigterm_leaves_nothing({}); }

// The signal lands just after the temporary is made, while the codec is set
// up: tests/shims/slow_temp.c holds the process there for 300 ms. The
// handler used to go in only after the writer was built, so this left the
// temporary behind (seen once in a loaded ctest run, every time with the shim).
// LD_PRELOAD's value with tests/shims/slow_temp.c after what is preloaded
// already (the sanitizer job's own stays first).
std::string preload_slow_temp() {
  const char* preload = std::getenv("LD_PRELOAD");
  return (preload && *preload ? std::string(preload) + ":" : std::string()) + MARCH_SLOW_TEMP_SHIM;
}

TEST(HugeStill, ASignalRightAfterTheTemporaryIsMadeRemovesIt) {
  expect_sigterm_leaves_nothing({"LD_PRELOAD=" + preload_slow_temp()});
}

TEST(HugeStill, ATimeoutStopsBetweenTilesAndLeavesNothing) {
  TempDir dir;
  // About a minute of work; --timeout 1 stops it at a tile's draw.
  const auto t0 = std::chrono::steady_clock::now();
  const RunResult r = run_marchstudio({"render", kSeed, "--size", "2048x2048", "--spp", "64", "--tile-still", "256",
                                       "--timeout", "1", "-o", "big.png"},
                                      dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("--timeout: the render did not finish within 1 s"), std::string::npos) << r.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20.0);
  EXPECT_TRUE(dir.entries().empty()) << "no file, no temporary";
}

// The deadline passes while the writer holds its new temporary (the shim
// holds it 3 s): the watchdog's hook was armed only after the writer was
// built, so the first watchdog (no hook) ended the process and left it.
TEST(HugeStill, ATimeoutRightAfterTheTemporaryIsMadeLeavesNothing) {
  TempDir dir;
  const RunResult r = run_marchstudio({"render", kSeed, "--size", "2048x2048", "--spp", "8", "--tile-still", "256",
                                       "--timeout", "1", "-o", "big.exr"},
                                      dir.path(), "SLOW_TEMP_MS=3000 LD_PRELOAD='" + preload_slow_temp() + "' ");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("--timeout: the render did not finish within 1 s"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.entries().empty()) << "no file, no temporary";
}

std::string counter_json() {
  return R"({"Shader": {"info": {"name": "t"}, "renderpass": [)"
         R"({"name": "Buffer A", "type": "buffer", "code": "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) + vec4(0.01); }", )"
         R"("inputs": [{"id": 257, "ctype": "buffer", "channel": 0}], "outputs": [{"id": 257, "channel": 0}]}, )"
         R"({"name": "Image", "type": "image", "code": "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0); }", )"
         R"("inputs": [{"id": 257, "ctype": "buffer", "channel": 0}], "outputs": []}]}})";
}

TEST(HugeStill, AShaderWithBuffersIsRefusedPastTheLimitsInOneLine) {
  TempDir dir;
  write_file(dir / "c.json", counter_json());
  const auto t0 = std::chrono::steady_clock::now();
  RunResult r = render((dir / "c.json").string(), dir / "big.png", {"--size", "9000x9000"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("--size: image size 9000x9000 needs "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a shader with buffers needs them whole-frame, so it cannot be drawn in tiles"),
            std::string::npos)
      << r.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0) << "before any GL";
  r = render((dir / "c.json").string(), dir / "small.png", {"--size", "64x64", "--tile-still", "32"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--tile-still: a shader with buffers"), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.json"});
}

TEST(HugeStill, PastTheLargestTiledSideIsRefused) {
  TempDir dir;
  const RunResult r = render(kSeed, dir / "x.png", {"--size", "70000x100"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("--size: image size 70000x100 is larger than 65536 pixels a side"), std::string::npos)
      << r.err;
  // A JPEG's own limit is a little less, refused before any tile is drawn.
  const RunResult jpeg = render(kSeed, dir / "x.jpg", {"--size", "65501x2"});
  EXPECT_EQ(jpeg.exit_code, 2) << jpeg.err;
  EXPECT_TRUE(one_line(jpeg.err)) << jpeg.err;
  EXPECT_NE(jpeg.err.find("a JPEG is at most 65500 pixels a side (libjpeg's limit), not 65501x2"), std::string::npos)
      << jpeg.err;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(HugeStill, ATerminalShowsATileBarWithAnEta) {
  if (!on_path("script")) GTEST_SKIP() << "script (util-linux) is not installed";
  TempDir dir;
  // script gives the command a pseudo-terminal and copies what it drew.
  const std::string cmd = "cd '" + dir.path().string() + "' && script -qec \"'" + std::string(MARCH_BIN) +
                          "' render '" + kSeed + "' --size 256x256 --tile-still 64 -o t.png\" typescript.txt" +
                          " > /dev/null 2>&1 < /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string tty = read_file(dir / "typescript.txt");
  EXPECT_NE(tty.find("\r[###############...............] 8/16 tiles"), std::string::npos) << tty;
  EXPECT_NE(tty.find("16/16 tiles"), std::string::npos) << tty;
  EXPECT_NE(tty.find("ETA "), std::string::npos) << tty;
  // Off a terminal (a log) no line per tile.
  const RunResult r = render(kSeed, dir / "log.png", {"--size", "256x256", "--tile-still", "64"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace ms::test
