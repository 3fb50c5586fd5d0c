// Cubemaps, through the real binary: six face PNGs the test
// writes land on their axes and in GL's orientation within each face; the
// Cube A pass's rayDir and fragCoord at texels the test picks, against GL's
// cube map table computed here; Cube A's read order (this frame's for the
// Image pass, the previous frame's for itself and for a buffer); an
// equirectangular EXR as six faces; bad and missing faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "io/image_io.h"
#include "run.h"
#include "shadertoy_json.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

std::string cube_input(int channel, const std::string& src, const std::string& filter = "linear",
                       const std::string& vflip = "false") {
  return "{\"id\": 22, \"ctype\": \"cubemap\", \"channel\": " + std::to_string(channel) + ", \"src\": \"" + src +
         "\", \"sampler\": {\"filter\": \"" + filter + "\", \"wrap\": \"clamp\", \"vflip\": \"" + vflip +
         "\", \"srgb\": \"false\"}}";
}
// Cube A as Shadertoy's JSON names it (the site's id and previz file).
std::string cube_a_input(int channel, const std::string& filter = "nearest") {
  return "{\"id\": \"4dX3Rr\", \"ctype\": \"cubemap\", \"channel\": " + std::to_string(channel) +
         ", \"src\": \"/media/previz/cubemap00.png\", \"sampler\": {\"filter\": \"" + filter +
         "\", \"wrap\": \"clamp\", \"vflip\": \"true\", \"srgb\": \"false\"}}";
}

// GL's cube map table (OpenGL 4.6, table 8.19), forwards: the face a
// direction picks, and (s, t) on it. Written here on its own, not taken
// from the code under test.
struct FacePoint {
  int face;
  double s, t;
};
FacePoint gl_face(double x, double y, double z) {
  const double ax = std::abs(x), ay = std::abs(y), az = std::abs(z);
  double sc, tc, ma;
  int face;
  if (ax >= ay && ax >= az) {
    face = x > 0 ? 0 : 1, ma = ax, sc = x > 0 ? -z : z, tc = -y;
  } else if (ay >= az) {
    face = y > 0 ? 2 : 3, ma = ay, sc = x, tc = y > 0 ? z : -z;
  } else {
    face = z > 0 ? 4 : 5, ma = az, sc = z > 0 ? x : -x, tc = -y;
  }
  return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}
// The inverse for a face and (s, t): a direction (not unit) through it.
std::array<double, 3> gl_direction(int face, double s, double t) {
  const double sc = 2 * s - 1, tc = 2 * t - 1;
  switch (face) {
    case 0: return {1, -tc, -sc};
    case 1: return {-1, -tc, sc};
    case 2: return {sc, 1, tc};
    case 3: return {sc, -1, -tc};
    case 4: return {sc, -tc, 1};
    default: return {-sc, -tc, -1};
  }
}

std::string vec3(const std::array<double, 3>& d) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "vec3(%.9f, %.9f, %.9f)", d[0], d[1], d[2]);
  return buf;
}
// An Image pass whose pixel x shows texture(iChannel0, dirs[x]).rgb, after `first`.
std::string sample_dirs(const std::vector<std::array<double, 3>>& dirs, const std::string& first = "") {
  std::string list;
  for (size_t i = 0; i < dirs.size(); ++i) list += (i ? ", " : "") + vec3(dirs[i]);
  const std::string n = std::to_string(dirs.size());
  return "const vec3 D[" + n + "] = vec3[" + n + "](" + list + ");\n"
         "void mainImage(out vec4 o, in vec2 f) { " + first + " o = vec4(texture(iChannel0, D[int(f.x)]).rgb, 1.0); }";
}

Image render(const TempDir& dir, std::vector<std::string> args, const std::string& out = "o.exr") {
  args.insert(args.begin(), "render");
  args.insert(args.end(), {"-o", out});
  const RunResult r = run_marchstudio(args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  return read_image(dir / out);
}

// A face: size x size, texel (x, y) (row 0 the file's top) is colour(x, y).
void write_face(const fs::path& p, int w, int h, const std::function<std::array<float, 3>(int, int)>& colour) {
  Image img;
  img.width = w;
  img.height = h;
  img.channels = {"R", "G", "B", "A"};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::array<float, 3> c = colour(x, y);
      img.pixels.insert(img.pixels.end(), {c[0], c[1], c[2], 1.0f});
    }
  write_image(img, p);
}
std::string face_name(int f) { return f == 0 ? "sky.png" : "sky_" + std::to_string(f) + ".png"; }
// Face f's solid colour, in 8-bit levels: all six differ in every channel.
std::array<float, 3> solid(int f) {
  return {(10.0f + 40 * f) / 255.0f, (250.0f - 30 * f) / 255.0f, (5.0f + 17 * ((f * 4) % 6)) / 255.0f};
}

const double kAxes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

TEST(Cubemap, SixFacePngsLandOnTheirAxes) {
  TempDir dir;
  for (int f = 0; f < 6; ++f) write_face(dir / face_name(f), 8, 8, [f](int, int) { return solid(f); });
  std::vector<std::array<double, 3>> dirs;
  for (const auto& a : kAxes) dirs.push_back({a[0], a[1], a[2]});
  dirs.push_back({1, 1, 1});
  // Pixel 6: iChannelResolution[0], the face size.
  const std::string code =
      sample_dirs(dirs, "if (int(f.x) == 6) { o = vec4(iChannelResolution[0], 1.0); return; }");
  write_file(dir / "c.json", shader({pass("Image", "image", "", code, cube_input(0, "/media/a/sky.png", "mipmap"))}));
  const Image img = render(dir, {"c.json", "--size", "7x1", "--media-dir", dir.path().string()});
  ASSERT_EQ(img.width, 7);
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(f, 0, c), solid(f)[c], 1e-6) << "face " << f << " channel " << c;
  EXPECT_EQ(img.at(6, 0, 0), 8.0f);
  EXPECT_EQ(img.at(6, 0, 1), 8.0f);
  EXPECT_EQ(img.at(6, 0, 2), 1.0f);
}

TEST(Cubemap, FaceTexelsSitWhereGlsTableSays) {
  // 2x2 faces, every texel of every face its own colour; nearest filtering
  // at the centre of each texel's quarter of the face.
  TempDir dir;
  const auto colour = [](int f, int x, int y) {
    return std::array<float, 3>{(20.0f + 9 * (4 * f + 2 * y + x)) / 255.0f, x ? 1.0f : 0.0f, y ? 1.0f : 0.0f};
  };
  for (int f = 0; f < 6; ++f) write_face(dir / face_name(f), 2, 2, [&](int x, int y) { return colour(f, x, y); });
  std::vector<std::array<double, 3>> dirs;
  for (int f = 0; f < 6; ++f)
    for (int q = 0; q < 4; ++q) dirs.push_back(gl_direction(f, 0.25 + 0.5 * (q % 2), 0.25 + 0.5 * (q / 2)));
  for (const bool vflip : {false, true}) {
    write_file(dir / "c.json", shader({pass("Image", "image", "", sample_dirs(dirs),
                                            cube_input(0, "/media/a/sky.png", "nearest", vflip ? "true" : "false"))}));
    const Image img = render(dir, {"c.json", "--size", "24x1", "--media-dir", dir.path().string()});
    ASSERT_EQ(img.width, 24);
    for (int f = 0; f < 6; ++f)
      for (int q = 0; q < 4; ++q) {
        // s runs along the file's columns; t = 0 is the file's top row (its bottom when vflip).
        const int x = q % 2, y = vflip ? 1 - q / 2 : q / 2;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(img.at(4 * f + q, 0, c), colour(f, x, y)[c], 1e-6)
              << "vflip " << vflip << " face " << f << " texel " << x << "," << y << " channel " << c;
      }
  }
}

TEST(Cubemap, AVsCodeWildcardNamesTheSixFaces) {
  // The VS Code extension's "sky_{}.png": sky_px.png, sky_nx.png .. sky_nz.png.
  TempDir dir;
  const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 6; ++f) write_face(dir / ("sky_" + std::string(names[f]) + ".png"), 4, 4, [f](int, int) { return solid(f); });
  std::vector<std::array<double, 3>> dirs;
  for (const auto& a : kAxes) dirs.push_back({a[0], a[1], a[2]});
  write_file(dir / "v.glsl", "#iChannel0 \"file://sky_{}.png\"\n#iChannel0::Type \"CubeMap\"\n" + sample_dirs(dirs) + "\n");
  const Image img = render(dir, {"v.glsl", "--size", "6x1"});
  ASSERT_EQ(img.width, 6);
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(f, 0, c), solid(f)[c], 1e-6) << "face " << f << " channel " << c;
}

// Directions through texel centres of a 1024 face: corners, edges and inner texels of each face.
std::vector<std::array<double, 3>> texel_dirs(std::vector<std::array<int, 3>>& texels) {
  const int picks[][2] = {{0, 0}, {1023, 0}, {0, 1023}, {1023, 1023}, {511, 700}, {37, 512}};
  std::vector<std::array<double, 3>> dirs;
  for (int f = 0; f < 6; ++f)
    for (const auto& p : picks) {
      texels.push_back({f, p[0], p[1]});
      dirs.push_back(gl_direction(f, (p[0] + 0.5) / 1024, (p[1] + 0.5) / 1024));
    }
  return dirs;
}

TEST(Cubemap, CubeAPassRayDirAndFragCoordFollowGlsFaces) {
  TempDir dir;
  std::vector<std::array<int, 3>> texels;
  const std::vector<std::array<double, 3>> dirs = texel_dirs(texels);
  const std::string size = std::to_string(dirs.size()) + "x1";
  // rayDir as colour, as Shadertoy's new-pass template does.
  write_file(dir / "dir.json",
             shader({pass("Cube A", "cubemap", "41",
                          "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = vec4(rd * 0.5 + 0.5, 1.0); }"),
                     pass("Image", "image", "", sample_dirs(dirs), cube_a_input(0))}));
  const Image d = render(dir, {"dir.json", "--size", size}, "d.exr");
  // fragCoord and |rayOri| (half floats hold these exactly).
  write_file(dir / "coord.json",
             shader({pass("Cube A", "cubemap", "41",
                          "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = vec4(f, length(ro), 1.0); }"),
                     pass("Image", "image", "", sample_dirs(dirs), cube_a_input(0))}));
  const Image c = render(dir, {"coord.json", "--size", size}, "c.exr");
  ASSERT_EQ(d.width, static_cast<int>(dirs.size()));
  ASSERT_EQ(c.width, static_cast<int>(dirs.size()));
  for (size_t i = 0; i < dirs.size(); ++i) {
    const auto& v = dirs[i];
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k)  // RGBA16F: within half a step of half precision at [0.5, 1]
      EXPECT_NEAR(d.at(static_cast<int>(i), 0, k), v[k] / n * 0.5 + 0.5, 5e-4)
          << "face " << texels[i][0] << " texel " << texels[i][1] << "," << texels[i][2] << " component " << k;
    // The texel GL reads for this direction is the one the pass drew it at.
    const FacePoint fp = gl_face(v[0], v[1], v[2]);
    ASSERT_EQ(fp.face, texels[i][0]);
    EXPECT_EQ(c.at(static_cast<int>(i), 0, 0), std::floor(fp.s * 1024) + 0.5) << "face " << fp.face;
    EXPECT_EQ(c.at(static_cast<int>(i), 0, 1), std::floor(fp.t * 1024) + 0.5) << "face " << fp.face;
    EXPECT_EQ(c.at(static_cast<int>(i), 0, 2), 0.0f);
  }
}

TEST(Cubemap, CubeAReadOrderIsShadertoys) {
  // Cube A counts frames on itself (reads its previous frame) and writes
  // iFrame and its iResolution.x; Buffer A (drawn before Cube A) copies
  // what Cube A held; the Image pass (drawn after) shows Cube A and Buffer A.
  TempDir dir;
  const std::string cube =
      "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) {\n"
      "  o = vec4(texture(iChannel0, rd).x + 1.0, float(iFrame), iResolution.x, 1.0); }";
  const std::string buf = "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel0, vec3(0.0, 0.0, -1.0)); }";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) { vec4 c = texture(iChannel0, vec3(0.3, 1.0, 0.2));\n"
      "  o = vec4(int(f.x) == 0 ? vec3(c.x, c.y, texelFetch(iChannel1, ivec2(0), 0).x) : vec3(c.z, 0.0, 0.0), 1.0); }";
  write_file(dir / "o.json", shader({pass("Image", "image", "", image, cube_a_input(0, "linear") +
                                                                          ", {\"id\": 257, \"ctype\": \"buffer\", \"channel\": 1}"),
                                     pass("Cube A", "cubemap", "41", cube, cube_a_input(0)),
                                     pass("Buffer A", "buffer", "257", buf, cube_a_input(0))}));
  const Image img = render(dir, {"o.json", "--size", "2x1", "--fps", "1", "--time", "4"});
  ASSERT_EQ(img.width, 2);
  EXPECT_EQ(img.at(0, 0, 0), 5.0f);  // frames 0..4 each added one
  EXPECT_EQ(img.at(0, 0, 1), 4.0f);  // this frame's iFrame: drawn before the Image pass
  EXPECT_EQ(img.at(0, 0, 2), 4.0f);  // Buffer A saw frame 3's count
  EXPECT_EQ(img.at(1, 0, 0), 1024.0f);
}

// Cube A counts frames on itself; Buffer A too, each in its own way.
std::string counting_json(bool with_buffer) {
  const std::string cube =
      "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = texture(iChannel0, rd) + vec4(1.0, 0.5, 0.25, 0.0); }";
  const std::string buf = "void mainImage(out vec4 o, in vec2 f) { o = texelFetch(iChannel0, ivec2(f), 0) * 0.5 + 1.0; }";
  const std::string image =
      "void mainImage(out vec4 o, in vec2 f) { vec3 d = vec3(f.x - 2.0, 1.0, f.y - 1.5);\n"
      "  o = vec4(texture(iChannel0, d).xy, texelFetch(iChannel1, ivec2(f), 0).x, 1.0); }";
  std::vector<std::string> passes = {pass("Cube A", "cubemap", "41", cube, cube_a_input(0))};
  if (with_buffer) passes.push_back(pass("Buffer A", "buffer", "257", buf, buffer_input(0, 257)));
  passes.push_back(pass("Image", "image", "", image,
                        cube_a_input(0) + (with_buffer ? ", {\"id\": 257, \"ctype\": \"buffer\", \"channel\": 1}" : "")));
  return shader(passes);
}

TEST(Cubemap, SequencesCheckpointCubeAAndResumeBitForBit) {
  for (const bool with_buffer : {true, false}) {
    TempDir whole, parts;
    write_file(whole / "s.json", counting_json(with_buffer));
    write_file(parts / "s.json", counting_json(with_buffer));
    const std::vector<std::string> args = {"render", "s.json", "--size", "4x3", "--fps", "10", "-o", "f_%d.exr"};
    const auto frames = [&](const std::string& range) {
      std::vector<std::string> a = args;
      a.insert(a.begin() + 2, {"--frames", range});
      return a;
    };
    RunResult r = run_marchstudio(frames("0..3"), whole.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Frames 0..1, then 0..3: the second run resumes after frame 1 from its checkpoint.
    r = run_marchstudio(frames("0..1"), parts.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> names = parts.entries();
    int cube_files = 0, states = 0;
    for (const std::string& n : names) {
      cube_files += n.size() > 15 && n.compare(n.size() - 15, 15, ".cube.state.exr") == 0;
      states += n.size() > 10 && n.compare(n.size() - 10, 10, ".state.exr") == 0;
    }
    EXPECT_EQ(cube_files, 1) << "only the last frame's Cube A state is kept";
    EXPECT_EQ(states, 2);
    r = run_marchstudio(frames("0..3"), parts.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("resuming after frame 1 from its checkpoint"), std::string::npos) << r.err;
    for (int f = 0; f <= 3; ++f) {
      const std::string name = "f_" + std::to_string(f) + ".exr";
      EXPECT_EQ(read_image(whole / name).pixels, read_image(parts / name).pixels) << name << " buffer " << with_buffer;
    }
    const Image last = read_image(parts / "f_3.exr");
    EXPECT_EQ(last.at(1, 1, 0), 4.0f);  // four frames counted on Cube A
    EXPECT_EQ(last.at(1, 1, 1), 2.0f);
    if (with_buffer) EXPECT_EQ(last.at(1, 1, 2), 1.875f);  // x -> x / 2 + 1, four times from 0
  }
}

// The nearest axis of a unit direction, 0..5 as the faces.
int nearest_axis(double x, double y, double z) {
  const double ax = std::abs(x), ay = std::abs(y), az = std::abs(z);
  if (ax >= ay && ax >= az) return x > 0 ? 0 : 1;
  if (ay >= az) return y > 0 ? 2 : 3;
  return z > 0 ? 4 : 5;
}

// Each ±axis's colour in the equirectangular test image.
std::array<float, 3> axis_colour(int a) { return {0.1f + 0.15f * a, 2.0f - 0.25f * a, a % 2 ? 0.75f : 3.5f}; }

// 128x64 float EXR, each pixel coloured by the axis nearest its direction
// under docs/shadertoy.md#cubemaps' layout (middle -Z, left edge +Z, top +Y).
void write_axis_equirect(const fs::path& p) {
  const double pi = 3.14159265358979323846;
  Image eq;
  eq.width = 128;
  eq.height = 64;
  eq.channels = {"R", "G", "B"};
  for (int y = 0; y < eq.height; ++y)
    for (int x = 0; x < eq.width; ++x) {
      const double lon = 2 * pi * (x + 0.5) / eq.width, lat = pi * (0.5 - (y + 0.5) / eq.height);
      const std::array<float, 3> c =
          axis_colour(nearest_axis(-std::cos(lat) * std::sin(lon), std::sin(lat), std::cos(lat) * std::cos(lon)));
      eq.pixels.insert(eq.pixels.end(), c.begin(), c.end());
    }
  write_image(eq, p);
}

// The six axes, then (0.2, 0.1, -1), inside -Z's region.
std::vector<std::array<double, 3>> axis_dirs() {
  std::vector<std::array<double, 3>> dirs;
  for (const auto& a : kAxes) dirs.push_back({a[0], a[1], a[2]});
  dirs.push_back({0.2, 0.1, -1});
  return dirs;
}
void expect_axis_colours(const Image& img, float tolerance) {
  ASSERT_EQ(img.width, 7);
  for (int i = 0; i < 7; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(img.at(i, 0, c), axis_colour(i == 6 ? 5 : i)[c], tolerance) << "direction " << i << " channel " << c;
}

TEST(Cubemap, AnEquirectangularExrBecomesSixFaces) {
  TempDir dir;
  write_axis_equirect(dir / "sky.exr");
  write_file(dir / "e.json", shader({pass("Image", "image", "", sample_dirs(axis_dirs()), cube_input(0, "/media/a/sky.exr"))}));
  expect_axis_colours(render(dir, {"e.json", "--size", "7x1", "--media-dir", dir.path().string()}), 1e-5f);
}

TEST(Cubemap, ATomlSceneWithACubemapPassAndAnEquirectangularFile) {
  // [[passes]]: Cube A copies sky.exr's cube (a samplerCube in the cube
  // pass), the Image pass reads Cube A (cubemap = "A").
  TempDir dir;
  write_axis_equirect(dir / "sky.exr");
  write_file(dir / "cube.glsl",
             "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = texture(iChannel0, rd); }\n");
  write_file(dir / "img.glsl", sample_dirs(axis_dirs()) + "\n");
  write_file(dir / "s.toml",
             "[scene]\nname = \"cube\"\n[render]\nwidth = 7\nheight = 1\n"
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { cubemap = \"A\", filter = \"nearest\" }\n"
             "[[passes]]\ntype = \"cubemap\"\nfile = \"cube.glsl\"\niChannel0 = { cubemap = \"sky.exr\" }\n");
  // Through Cube A's half floats: within half a step at 3.5.
  expect_axis_colours(render(dir, {"s.toml"}), 2e-3f);
  // cubemap = "A" without a cubemap pass; a cubemap file that is not there.
  write_file(dir / "bad.toml", "[scene]\nname = \"b\"\n[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\n"
                               "iChannel0 = { cubemap = \"A\" }\n");
  RunResult r = run_marchstudio({"render", "bad.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Image iChannel0 reads Cube A, which no pass writes"), std::string::npos) << r.err;
  write_file(dir / "bad.toml", "[scene]\nname = \"b\"\n[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\n"
                               "iChannel0 = { cubemap = \"nowhere.exr\" }\n");
  r = run_marchstudio({"render", "bad.toml", "-o", "x.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.toml:6: passes[0].iChannel0.cubemap: cubemap"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(Cubemap, BadOrMissingFacesAreOneLineErrors) {
  TempDir dir;
  const std::string code = sample_dirs({{1, 0, 0}});
  write_file(dir / "c.json", shader({pass("Image", "image", "", code, cube_input(0, "/media/a/sky.png"))}));
  const auto expect_error = [&](const std::string& says, const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {"render", "c.json", "--media-dir", dir.path().string(), "-o", "x.png"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_marchstudio(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
  };
  for (int f = 0; f < 6; ++f) write_face(dir / face_name(f), 4, 4, [f](int, int) { return solid(f); });
  write_face(dir / face_name(3), 8, 8, [](int, int) { return solid(3); });
  expect_error("sky_3.png: cubemap face 3 (-Y) is 8x8, but face 0 (");
  write_face(dir / face_name(3), 4, 4, [](int, int) { return solid(3); });
  write_face(dir / face_name(0), 4, 2, [](int, int) { return solid(0); });
  expect_error("sky.png: cubemap face 0 (+X) is 4x2, not square");
  write_face(dir / face_name(0), 4, 4, [](int, int) { return solid(0); });
  fs::remove(dir / face_name(5));
  expect_error("Image iChannel0: cubemap '/media/a/sky.png' face 'sky_5.png' is not in the media directory");
  // With --missing-media black: black faces, and a warning.
  const RunResult r = run_marchstudio(
      {"render", "c.json", "--media-dir", dir.path().string(), "--size", "1x1", "--missing-media", "black", "-o", "b.exr"},
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("face 'sky_5.png' is missing; black stands in"), std::string::npos) << r.err;
  const Image b = read_image(dir / "b.exr");
  EXPECT_EQ(b.at(0, 0, 0), 0.0f);
  EXPECT_EQ(b.at(0, 0, 1), 0.0f);
  // A Cube A pass without mainCubemap (a Cube A input with no Cube A pass
  // reads 0: test_shadertoy_rules.cpp).
  write_file(dir / "c.json", shader({pass("Cube A", "cubemap", "41", "void mainImage(out vec4 o, in vec2 f) { o = vec4(1); }"),
                                     pass("Image", "image", "", code, cube_a_input(0))}));
  expect_error("no mainCubemap() found in the Cube A pass");
}

}  // namespace
}  // namespace ms::test
