// What comes in broken must leave as one line and well-formed reports: an
// image module cut short (SIGBUS inside dlopen), a FIFO in its place (a
// hang inside dlopen) or a text file; a compile error quoting a byte that
// is not UTF-8 (test --json threw, the JUnit XML was ill-formed); a corrupt
// PNG texture (libpng printed its own line before ours).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/utf8.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const char* kMain = "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / 64.0, f.y / 36.0, 0.5, 1.0); }\n";

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

fs::path module_path() { return fs::path(MARCH_BIN).parent_path() / "marchstudio-oiio.so"; }

TEST(ImageModule, ACutCopyAFifoOrATextFileIsOneLineExitThree) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  const std::string whole = read_file(module_path());
  ASSERT_GT(whole.size(), 4096u) << module_path();
  write_file(dir / "half.so", whole.substr(0, whole.size() / 2));
  write_file(dir / "tail.so", whole.substr(0, whole.size() - 64));  // only the section table cut
  write_file(dir / "text.so", "not a shared object\n");
  ASSERT_EQ(::mkfifo((dir / "fifo.so").c_str(), 0600), 0);
  for (const char* module : {"half.so", "tail.so", "text.so", "fifo.so"}) {
    // timeout: before the checks a FIFO hung in dlopen for ever.
    const std::string prefix = "MARCH_IMAGE_MODULE='" + (dir / module).string() + "' timeout 120 ";
    const RunResult r = run_marchstudio({"render", "m.glsl", "--size", "16x16", "-o", "o.jpg"}, dir.path(), prefix);
    EXPECT_EQ(r.exit_code, 3) << module << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << module << ": " << r.err;
    EXPECT_NE(r.err.find("cannot load the image I/O module"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "o.jpg")) << module;
  }
  // A PNG needs no module: a broken one loaded in the background does not end the render.
  const std::string prefix = "MARCH_IMAGE_MODULE='" + (dir / "half.so").string() + "' timeout 120 ";
  const RunResult png = run_marchstudio({"render", "m.glsl", "--size", "16x16", "-o", "o.png"}, dir.path(), prefix);
  EXPECT_EQ(png.exit_code, 0) << png.err;
}

// Whether /usr/bin/python3's XML parser accepts `file`.
bool xml_parses(const fs::path& file) {
  const std::string cmd =
      "/usr/bin/python3 -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' '" + file.string() + "'";
  return std::system(cmd.c_str()) == 0;
}

TEST(NonUtf8Text, ReportsStayWellFormedAndTheByteBecomesFffd) {
  TempDir dir;
  // #error echoes its text: the compile error quotes the byte 0xff.
  write_file(dir / "bad.glsl", "#error caf\xff\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
  write_file(dir / "s.toml",
             "[[case]]\nname = \"bad\"\nscene = \"bad.glsl\"\nsize = [16, 16]\nreference = \"none.png\"\n"
             "metric = \"psnr\"\nthreshold = 40\n");
  const RunResult r = run_marchstudio({"test", "s.toml", "--json", "--junit", "j.xml"}, dir.path(),
                                      "MESA_SHADER_CACHE_DIR='" + (dir / "cache").string() + "' ");
  EXPECT_EQ(r.exit_code, 2) << r.err;  // the case could not run; not an internal error
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  ASSERT_FALSE(r.out.empty()) << r.err;
  EXPECT_TRUE(is_valid_utf8(r.out));
  EXPECT_NE(r.out.find("caf\xef\xbf\xbd"), std::string::npos) << r.out;  // U+FFFD where 0xff was
  EXPECT_TRUE(is_valid_utf8(r.err)) << r.err;
  const std::string xml = read_file(dir / "j.xml");
  EXPECT_TRUE(is_valid_utf8(xml));
  EXPECT_NE(xml.find("caf\xef\xbf\xbd"), std::string::npos) << xml;
  write_file(dir / "out.json", r.out);
  EXPECT_TRUE(xml_parses(dir / "j.xml")) << xml;
  const std::string json_cmd =
      "/usr/bin/python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding=\"utf-8\"))' '" +
      (dir / "out.json").string() + "'";
  EXPECT_EQ(std::system(json_cmd.c_str()), 0) << r.out;
}

// A PNG whose zlib stream is broken, and one cut inside its header chunks.
void write_broken_pngs(const TempDir& dir) {
  ASSERT_EQ(run_marchstudio({"render", "m.glsl", "--size", "64x36", "-o", "good.png"}, dir.path()).exit_code, 0);
  const std::string good = read_file(dir / "good.png");
  std::string corrupt = good;
  const size_t idat = corrupt.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  for (size_t k = idat + 8; k < idat + 40 && k < corrupt.size(); ++k) corrupt[k] ^= 0x55;
  write_file(dir / "corrupt.png", corrupt);
  write_file(dir / "cut.png", good.substr(0, std::min<size_t>(good.size(), idat - 20)));
}

TEST(CorruptPng, ATextureGivesOurOneLineOnly) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  write_broken_pngs(dir);
  write_file(dir / "t.frag",
             "uniform sampler2D u_tex0;\nuniform vec2 u_resolution;\n"
             "void main() { gl_FragColor = texture2D(u_tex0, gl_FragCoord.xy / u_resolution); }\n");
  for (const char* png : {"corrupt.png", "cut.png"}) {
    const RunResult r = run_marchstudio({"render", "t.frag", "--texture", png, "--size", "16x16", "-o", "o.png"},
                                        dir.path());
    EXPECT_EQ(r.exit_code, 2) << png << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1) << png << ": " << r.err;
    EXPECT_EQ(r.err.rfind("marchstudio: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "o.png"));
  }
}

// A JPEG cut inside its header: OpenImageIO reports two messages, one a
// line; ours joins them as clauses rather than showing an escaped "\n".
TEST(CorruptJpeg, HeaderCutShortIsOneLineWithoutEscapedBreaks) {
  TempDir dir;
  write_file(dir / "m.glsl", kMain);
  ASSERT_EQ(run_marchstudio({"render", "m.glsl", "--size", "16x16", "-o", "ok.jpg"}, dir.path()).exit_code, 0);
  write_file(dir / "cut.jpg", read_file(dir / "ok.jpg").substr(0, 100));
  const RunResult r = run_marchstudio({"info", "cut.jpg"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cut.jpg"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\\n"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
