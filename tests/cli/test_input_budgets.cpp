// Small files that declare gigabytes, through the real binary: each is
// refused from its header (exit 2, one line naming the file and the memory
// budget) before anything of that size is allocated. The address space is
// capped at 2 GB, so a run that still allocated would die of it (exit 3 or
// a signal) instead. Also: a JPEG cut short is an error as a cut PNG is,
// and a texture past GL_MAX_TEXTURE_SIZE names its file and the limit.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::string kLimit = address_space_limit(2000000);

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (const unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

std::string png_chunk(const std::string& type, const std::string& data) {
  return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc32(type + data));
}

// 65 bytes: an RGBA PNG that declares 100000x100000 (an empty zlib stream).
std::string huge_png() {
  const std::string ihdr = be32(100000) + be32(100000) + std::string("\x08\x06\x00\x00\x00", 5);
  const std::string idat("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
  return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", idat) +
         png_chunk("IEND", "");
}

// A real JPEG with its frame header (SOF0) rewritten to 65500x65500.
std::string huge_jpeg(const fs::path& scratch) {
  Image img;
  img.width = img.height = 16;
  img.channels = {"R", "G", "B"};
  img.pixels.assign(16 * 16 * 3, 0.5f);
  write_image(img, scratch);
  std::string b = read_file(scratch);
  for (std::size_t i = 2; i + 9 < b.size();) {
    const auto m = static_cast<unsigned char>(b[i + 1]);
    if (m == 0xC0 || m == 0xC1 || m == 0xC2) {
      b[i + 5] = b[i + 7] = static_cast<char>(0xFF);
      b[i + 6] = b[i + 8] = static_cast<char>(0xDC);  // 0xFFDC = 65500
      return b;
    }
    i += 2 + ((static_cast<std::size_t>(static_cast<unsigned char>(b[i + 2])) << 8) |
              static_cast<unsigned char>(b[i + 3]));
  }
  ADD_FAILURE() << "no SOF marker";
  return b;
}

// A VS Code shader reading `file` through iChannel0.
std::string reads(const std::string& file) {
  return "#iChannel0 \"file://" + file + "\"\n"
         "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f / 8.0); }\n";
}

void expect_refused(const RunResult& r, const std::string& file, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("marchstudio: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(file + ": " + what), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("over the"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("memory budget"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
}

TEST(InputBudget, ImageHeadersDeclaringGigabytesAreRefusedBeforeDecoding) {
  TempDir dir;
  write_file(dir / "huge.png", huge_png());
  ASSERT_LT(read_file(dir / "huge.png").size(), 70u);
  write_file(dir / "huge.jpg", huge_jpeg(dir / "small.jpg"));
  write_file(dir / "huge.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n") +
                                   std::string(16, '\0'));
  for (const std::string name : {"huge.png", "huge.jpg", "huge.hdr"}) {
    write_file(dir / "t.glsl", reads(name));
    const RunResult r = run_marchstudio({"render", "t.glsl", "--size", "8x8", "-o", "o.png"}, dir.path(), kLimit);
    expect_refused(r, name, "the image is ");
    EXPECT_FALSE(fs::exists(dir / "o.png")) << name;
  }
}

TEST(InputBudget, AnEquirectangularStripIsRefusedBeforeItsSixFaces) {
  TempDir dir;
  Image strip;  // 60000x1: six 15000^2 float faces, 20 GiB
  strip.width = 60000;
  strip.height = 1;
  strip.channels = {"R", "G", "B"};
  strip.pixels.assign(60000 * 3, 1.0f);
  write_image(strip, dir / "strip.exr");
  write_file(dir / "cube.glsl",
             "void mainCubemap(out vec4 o, in vec2 f, in vec3 ro, in vec3 rd) { o = texture(iChannel0, rd); }\n");
  write_file(dir / "img.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec3(1, 0, 0)); }\n");
  write_file(dir / "s.toml",
             "[scene]\nname = \"cube\"\n[render]\nwidth = 4\nheight = 1\n"
             "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { cubemap = \"A\" }\n"
             "[[passes]]\ntype = \"cubemap\"\nfile = \"cube.glsl\"\niChannel0 = { cubemap = \"strip.exr\" }\n");
  const RunResult r = run_marchstudio({"render", "s.toml", "-o", "o.png"}, dir.path(), kLimit);
  expect_refused(r, "strip.exr", "a cubemap of six 15000x15000 float faces needs");
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

TEST(InputBudget, AFlacClaiming2To36FramesIsRefusedFromItsHeader) {
  TempDir dir;
  // STREAMINFO: block sizes 4096, frame sizes unknown, 44100 Hz, mono,
  // 16 bits, 2^36 - 1 frames, no MD5; then no audio frames at all.
  const std::uint64_t bits = (std::uint64_t{44100} << 44) | (std::uint64_t{15} << 36) | ((std::uint64_t{1} << 36) - 1);
  std::string info = std::string("\x10\x00\x10\x00", 4) + std::string(6, '\0');
  for (int i = 7; i >= 0; --i) info += static_cast<char>(bits >> (8 * i));
  info += std::string(16, '\0');
  ASSERT_EQ(info.size(), 34u);
  write_file(dir / "big.flac", std::string("fLaC\x80\x00\x00\x22", 8) + info);
  write_file(dir / "a.glsl", reads("big.flac"));
  const RunResult r = run_marchstudio({"render", "a.glsl", "--size", "8x8", "-o", "o.png"}, dir.path(), kLimit);
  expect_refused(r, "big.flac", "a clip of 68719476735 frames needs");
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

TEST(InputBudget, ShadertoyJsonWith40000NestedArraysLoadsInLinearMemory) {
  TempDir dir;
  // The line map kept each value's whole key path: 40,000 nested arrays
  // under a key nobody reads needed 5 GB; the shader itself is fine.
  const std::string deep = std::string(40000, '[') + std::string(40000, ']');
  write_file(dir / "deep.json",
             "{\"Shader\": {\"info\": {\"name\": \"deep\"}, \"junk\": " + deep +
                 ", \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", \"code\": "
                 "\"void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }\", \"inputs\": [], \"outputs\": []}]}}");
  const RunResult r = run_marchstudio({"render", "deep.json", "--size", "8x8", "-o", "o.png"}, dir.path(), kLimit);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "o.png"));
}

TEST(TextureChecks, AJpegCutInHalfIsAnErrorAsACutPngIs) {
  TempDir dir;
  Image img;  // noise: a JPEG whose scan data fills most of the file
  img.width = img.height = 128;
  img.channels = {"R", "G", "B"};
  std::uint32_t s = 1;
  for (int i = 0; i < 128 * 128 * 3; ++i) {
    s = s * 1664525u + 1013904223u;
    img.pixels.push_back(static_cast<float>(s >> 24) / 255.0f);
  }
  write_image(img, dir / "full.jpg");
  const std::string whole = read_file(dir / "full.jpg");
  write_file(dir / "cut.jpg", whole.substr(0, whole.size() / 2));
  write_file(dir / "t.glsl", reads("full.jpg"));
  const RunResult ok = run_marchstudio({"render", "t.glsl", "--size", "8x8", "-o", "o.png"}, dir.path());
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  fs::remove(dir / "o.png");
  write_file(dir / "t.glsl", reads("cut.jpg"));
  const RunResult r = run_marchstudio({"render", "t.glsl", "--size", "8x8", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cut.jpg: cannot decode image: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cut short"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

TEST(TextureChecks, ATextureWiderThanTheGlLimitNamesTheFileAndTheLimit) {
  TempDir dir;
  Image wide;  // llvmpipe's GL_MAX_TEXTURE_SIZE is 16384; a real GPU's may be larger
  wide.width = 65536;
  wide.height = 1;
  wide.channels = {"R", "G", "B"};
  wide.pixels.assign(65536 * 3, 0.5f);
  write_image(wide, dir / "wide.png");
  write_file(dir / "t.glsl", reads("wide.png"));
  const RunResult r = run_marchstudio({"render", "t.glsl", "--size", "8x8", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("wide.png: the texture is 65536x1, larger than this GL's GL_MAX_TEXTURE_SIZE of "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("GL error"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

}  // namespace
}  // namespace ms::test
