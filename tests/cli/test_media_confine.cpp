// Media confinement through the real binary: a texture, a cube face, an
// audio clip or a [sky] environment is read only from the scene's folder,
// --media-dir and --allow-include, judged where it leads (symlinks
// resolved). A path out of the scene, a symlink beside a downloaded shader
// or inside the media directory, and a VS Code "sky_{}.png" whose faces
// lead elsewhere are each one line, exit 2, no output; --allow-include of
// the other directory lets them through. A Shadertoy "/media/a/" name in a
// scene's [[passes]] is found in the media directory, as documented.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A 4x4 PNG of one colour (8-bit levels).
void write_png(const fs::path& p, std::array<int, 3> rgb) {
  Image img;
  img.width = img.height = 4;
  img.channels = {"R", "G", "B", "A"};
  for (int i = 0; i < 16; ++i)
    img.pixels.insert(img.pixels.end(), {rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f, 1.0f});
  fs::create_directories(p.parent_path());
  write_image(img, p);
}

// <tmp>/scene (the shader), <tmp>/media, and <tmp>/outside with a red
// x.png that nothing may read unless --allow-include names it.
struct Layout {
  TempDir dir;
  Layout() {
    fs::create_directories(dir / "scene");
    fs::create_directories(dir / "media");
    write_png(dir / "outside" / "x.png", {255, 0, 0});
  }
  RunResult render(std::vector<std::string> args) {
    args.insert(args.begin(), "render");
    args.insert(args.end(), {"--size", "4x4", "-o", "o.png"});
    return run_marchstudio(args, dir.path());
  }
};

// Refused: exit 2, one line naming `name` and the rule, no image.
void expect_refused(const Layout& l, const RunResult& r, const std::string& name) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("outside the directories"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-include"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(l.dir / "o.png"));
}

const char* kShow = "void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(0), 0).rgb, 1.0); }";

std::string json_with(const std::string& ctype, const std::string& src, const std::string& code = kShow) {
  return "{\"Shader\": {\"info\": {\"name\": \"m\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
         "\"code\": \"" + code + "\", \"inputs\": [{\"id\": 1, \"ctype\": \"" + ctype +
         "\", \"channel\": 0, \"src\": \"" + src +
         "\", \"sampler\": {\"filter\": \"nearest\", \"wrap\": \"clamp\", \"vflip\": \"false\", \"srgb\": \"false\"}}], "
         "\"outputs\": []}]}}";
}

std::string passes_toml(const std::string& channel) {
  return "[scene]\nname = \"t\"\n[render]\nwidth = 4\nheight = 4\n"
         "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = " + channel + "\n";
}

TEST(MediaConfine, AVsCodeCubemapFaceLeadingOutsideIsRefusedByName) {
  Layout l;
  const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 5; ++f) write_png(l.dir / "scene" / ("sky_" + std::string(names[f]) + ".png"), {0, 255, 0});
  // The sixth face is a symlink out of the scene; the literal "sky_{}.png" lies inside.
  fs::create_symlink("../outside/x.png", l.dir / "scene" / "sky_nz.png");
  write_file(l.dir / "scene" / "v.glsl", "#iChannel0 \"file://sky_{}.png\"\n#iChannel0::Type \"CubeMap\"\n"
                                         "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel0, vec3(0.0, 0.0, -1.0)); }\n");
  const RunResult r = l.render({"scene/v.glsl"});
  expect_refused(l, r, "sky_nz.png");
  EXPECT_NE(r.err.find("v.glsl:1"), std::string::npos) << r.err;
  const RunResult ok = l.render({"scene/v.glsl", "--allow-include", "outside"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST(MediaConfine, ACubemapFaceSymlinkInTheMediaDirIsRefusedByName) {
  Layout l;
  write_png(l.dir / "media" / "sky.png", {0, 255, 0});
  for (int f = 1; f < 6; ++f)
    if (f != 3) write_png(l.dir / "media" / ("sky_" + std::to_string(f) + ".png"), {0, 255, 0});
  fs::create_symlink("../outside/x.png", l.dir / "media" / "sky_3.png");
  write_file(l.dir / "scene" / "c.json",
             json_with("cubemap", "/media/a/sky.png",
                       "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel0, vec3(0.0, -1.0, 0.0)); }"));
  expect_refused(l, l.render({"scene/c.json", "--media-dir", "media"}), "sky_3.png");
  const RunResult ok = l.render({"scene/c.json", "--media-dir", "media", "--allow-include", "outside"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST(MediaConfine, ATexturePathOutOfTheSceneIsRefused) {
  Layout l;
  write_file(l.dir / "scene" / "img.glsl", std::string(kShow) + "\n");
  write_file(l.dir / "scene" / "t.toml", passes_toml("{ texture = \"../outside/x.png\" }"));
  expect_refused(l, l.render({"scene/t.toml"}), "../outside/x.png");
  const RunResult ok = l.render({"scene/t.toml", "--allow-include", "outside"});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const Image img = read_image(l.dir / "o.png");
  EXPECT_NEAR(img.at(0, 0, 0), 1.0f, 1e-6);  // the red of outside/x.png
}

TEST(MediaConfine, SymlinksInTheMediaDirOrBesideTheShaderAreJudgedWhereTheyLead) {
  Layout l;
  fs::create_symlink("../outside/x.png", l.dir / "media" / "h.png");
  fs::create_symlink("../outside/x.png", l.dir / "scene" / "h.png");
  write_file(l.dir / "scene" / "m.json", json_with("texture", "/media/a/h.png"));
  expect_refused(l, l.render({"scene/m.json", "--media-dir", "media"}), "h.png");
  expect_refused(l, l.render({"scene/m.json"}), "h.png");  // the default media dir: the shader's own
  const RunResult ok = l.render({"scene/m.json", "--media-dir", "media", "--allow-include", "outside"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  // A file really inside the media directory still reads.
  write_png(l.dir / "media" / "b.png", {0, 0, 255});
  write_file(l.dir / "scene" / "b.json", json_with("texture", "/media/a/b.png"));
  EXPECT_EQ(l.render({"scene/b.json", "--media-dir", "media"}).exit_code, 0);
}

// A scene's own media_dir is a path from the scene: it is not a root.
TEST(MediaConfine, AScenesMediaDirOutsideItsFolderIsNotARoot) {
  Layout l;
  write_file(l.dir / "scene" / "img.glsl", std::string(kShow) + "\n");
  write_file(l.dir / "scene" / "t.toml",
             "[shadertoy]\nmedia_dir = \"../outside\"\n" + passes_toml("{ texture = \"/media/a/x.png\" }"));
  expect_refused(l, l.render({"scene/t.toml"}), "x.png");
  EXPECT_EQ(l.render({"scene/t.toml", "--allow-include", "outside"}).exit_code, 0);
}

// 16-bit mono PCM at 44100 Hz, `n` samples of silence.
std::string wav(int n) {
  std::string s;
  const auto u32 = [&s](std::uint32_t v) { for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>(v >> (8 * i))); };
  const auto u16 = [&s](std::uint16_t v) { for (int i = 0; i < 2; ++i) s.push_back(static_cast<char>(v >> (8 * i))); };
  s += "RIFF";
  u32(36 + 2 * n);
  s += "WAVEfmt ";
  u32(16), u16(1), u16(1), u32(44100), u32(88200), u16(2), u16(16);
  s += "data";
  u32(2 * n);
  s.append(static_cast<size_t>(2 * n), '\0');
  return s;
}

TEST(MediaConfine, AnAudioSymlinkLeadingOutsideIsRefused) {
  Layout l;
  write_file(l.dir / "outside" / "s.wav", wav(4410));
  fs::create_symlink("../outside/s.wav", l.dir / "media" / "s.wav");
  write_file(l.dir / "scene" / "a.json", json_with("music", "/media/a/s.wav"));
  expect_refused(l, l.render({"scene/a.json", "--media-dir", "media"}), "s.wav");
  EXPECT_EQ(l.render({"scene/a.json", "--media-dir", "media", "--allow-include", "outside"}).exit_code, 0);
}

TEST(MediaConfine, AnEnvironmentOutOfTheSceneIsRefused) {
  Layout l;
  Image m;
  m.width = 8;
  m.height = 4;
  m.channels = {"R", "G", "B"};
  m.pixels.assign(8 * 4 * 3, 0.5f);
  write_image(m, l.dir / "outside" / "sky.exr");
  write_file(l.dir / "scene" / "m.glsl", "vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, 0.0, 6.0), 1.0), MAT_BALL); }\n");
  write_file(l.dir / "scene" / "s.toml",
             "[scene]\nname = \"env\"\nmap = \"m.glsl\"\n[render]\nwidth = 4\nheight = 4\n"
             "[sky]\nenvironment = \"../outside/sky.exr\"\n"
             "[[materials]]\nname = \"ball\"\ncolor = [1.0, 1.0, 1.0]\n");
  const std::string cache = "XDG_CACHE_HOME='" + (l.dir / "cache").string() + "' ";
  const RunResult r = run_marchstudio({"render", "scene/s.toml", "-o", "o.png"}, l.dir.path(), cache);
  expect_refused(l, r, "sky.exr");
  EXPECT_NE(r.err.find("sky.environment"), std::string::npos) << r.err;
  const RunResult ok =
      run_marchstudio({"render", "scene/s.toml", "-o", "o.png", "--allow-include", "outside"}, l.dir.path(), cache);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

// docs/scene-format.md: a [[passes]] texture may be a Shadertoy
// "/media/a/..." name, looked up by file name in the media directory.
TEST(MediaConfine, AShadertoyMediaNameInPassesIsFoundInTheMediaDir) {
  Layout l;
  write_png(l.dir / "media" / "b.png", {0, 0, 255});
  write_file(l.dir / "scene" / "img.glsl", std::string(kShow) + "\n");
  write_file(l.dir / "scene" / "t.toml", passes_toml("{ texture = \"/media/a/b.png\" }"));
  const RunResult r = l.render({"scene/t.toml", "--media-dir", "media"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(l.dir / "o.png");
  EXPECT_NEAR(img.at(0, 0, 0), 0.0f, 1e-6);
  EXPECT_NEAR(img.at(0, 0, 2), 1.0f, 1e-6);
  // Not there: the media directory's error, not a path from the filesystem root.
  write_file(l.dir / "scene" / "t.toml", passes_toml("{ texture = \"/media/a/gone.png\" }"));
  const RunResult gone = l.render({"scene/t.toml", "--media-dir", "media"});
  EXPECT_EQ(gone.exit_code, 2);
  EXPECT_NE(gone.err.find("is not in the media directory"), std::string::npos) << gone.err;
}

}  // namespace
}  // namespace ms::test
