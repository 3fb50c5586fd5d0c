// importers/project_json.h on hand-written files: the API form and the site's
// export form with every field, Shadertoy's pass order and sampler
// defaults, and each kind of bad input with its line and key.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "importers/es_compat.h"
#include "importers/project_json.h"

namespace ms {
namespace {

// The API's form: passes in a shuffled order, numeric buffer ids.
const char* kApi = R"({"Shader": {
  "ver": "0.1",
  "info": {"id": "abcd12", "name": "Feedback test", "username": "us", "description": "d", "tags": ["x"]},
  "renderpass": [
    {"name": "Image", "type": "image", "code": "void mainImage(out vec4 o, in vec2 f) { o = texture(iChannel0, f); }",
     "inputs": [{"id": 257, "src": "/media/previz/buffer00.png", "ctype": "buffer", "channel": 0,
                 "sampler": {"filter": "nearest", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"},
                 "published": 1},
                {"id": 17, "src": "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png",
                 "ctype": "texture", "channel": 2, "published": 1}],
     "outputs": [{"id": 37, "channel": 0}]},
    {"name": "Buffer B", "type": "buffer", "code": "// b", "inputs": [{"id": 33, "src": "", "ctype": "keyboard", "channel": 3}],
     "outputs": [{"id": 258, "channel": 0}]},
    {"name": "Common", "type": "common", "code": "#define K 1", "inputs": [], "outputs": []},
    {"name": "Buffer A", "type": "buffer", "code": "// a",
     "inputs": [{"id": 257, "ctype": "buffer", "channel": 1, "sampler": {"filter": "mipmap", "wrap": "repeat"}}],
     "outputs": [{"id": 257, "channel": 0}]},
    {"name": "Sound", "type": "sound", "code": "vec2 mainSound(int s, float t) { return vec2(0); }", "inputs": [], "outputs": []}
  ]}})";

TEST(ProjectJson, TheApiFormInShadertoysOrder) {
  const ShaderProject p = load_shadertoy_json(kApi, "x.json");
  EXPECT_EQ(p.name, "Feedback test");
  EXPECT_EQ(p.common, "#define K 1");
  EXPECT_TRUE(p.has_sound);
  ASSERT_EQ(p.warnings.size(), 1u);  // said once, and --strict refuses it
  EXPECT_NE(p.warnings[0].find("Sound pass (mainSound) is not run"), std::string::npos);
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].name, "Buffer A");
  EXPECT_EQ(p.passes[0].output, 0);
  EXPECT_EQ(p.passes[1].name, "Buffer B");
  EXPECT_EQ(p.passes[1].output, 1);
  EXPECT_EQ(p.passes[2].kind, PassKind::image);
  EXPECT_EQ(p.passes[2].where, "x.json (Image)");
  // Buffer A reads itself, mipmapped.
  const ProjectInput& self = p.passes[0].inputs[1];
  EXPECT_EQ(self.kind, InputKind::buffer);
  EXPECT_EQ(self.buffer, 0);
  EXPECT_EQ(self.sampler.filter, TexFilter::mipmap);
  EXPECT_EQ(self.sampler.wrap, TexWrap::repeat);
  EXPECT_EQ(p.passes[1].inputs[3].kind, InputKind::keyboard);
  const ProjectInput& buf = p.passes[2].inputs[0];
  EXPECT_EQ(buf.buffer, 0);
  EXPECT_EQ(buf.sampler.filter, TexFilter::nearest);
  EXPECT_TRUE(buf.sampler.vflip);
  // A texture without a sampler gets Shadertoy's texture defaults.
  const ProjectInput& tex = p.passes[2].inputs[2];
  EXPECT_EQ(tex.kind, InputKind::texture);
  EXPECT_EQ(tex.src, "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png");
  EXPECT_EQ(tex.sampler.filter, TexFilter::mipmap);
  EXPECT_EQ(tex.sampler.wrap, TexWrap::repeat);
  EXPECT_TRUE(tex.sampler.vflip);
  EXPECT_EQ(p.passes[2].inputs[1].kind, InputKind::none);
}

// The site's export: an array of shaders, `type` and `filepath`, string ids.
const char* kExport = R"([{"ver": "0.1", "info": {"name": "exported"},
  "renderpass": [
    {"inputs": [{"id": "XsXGR8", "filepath": "/media/previz/buffer01.png", "type": "buffer", "channel": 0,
                 "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false"}},
                {"id": "4dXGR8", "filepath": "/media/previz/buffer00.png", "type": "buffer", "channel": 1}],
     "outputs": [{"id": "4dfGRr", "channel": 0}], "code": "void mainImage(out vec4 o, in vec2 f) {}",
     "name": "Image", "description": "", "type": "image"},
    {"inputs": [], "outputs": [{"id": "XsXGR8", "channel": 0}], "code": "// b", "name": "Buffer B", "type": "buffer"},
    {"inputs": [], "outputs": [{"id": "4dXGR8", "channel": 0}], "code": "// a", "name": "Buffer A", "type": "buffer"}
  ]}])";

TEST(ProjectJson, TheSiteExportForm) {
  const ShaderProject p = load_shadertoy_json(kExport, "e.json");
  EXPECT_EQ(p.name, "exported");
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].output, 0);
  EXPECT_EQ(p.passes[1].output, 1);
  EXPECT_EQ(p.passes[2].inputs[0].buffer, 1);
  EXPECT_EQ(p.passes[2].inputs[1].buffer, 0);
  EXPECT_TRUE(p.warnings.empty());
}

std::string error_of(const std::string& text) {
  try {
    load_shadertoy_json(text, "bad.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ProjectJson, BadInputNamesLineAndKey) {
  EXPECT_EQ(error_of("{\"Shader\": {\n\"renderpass\": [\n{\"type\": \"image\",, }]}}"),
            "bad.json:3: malformed JSON at column 18: syntax error while parsing object key - unexpected ','; "
            "expected string literal");
  EXPECT_EQ(error_of("{\"nope\": 1}").substr(0, 40), "bad.json: no 'renderpass' array: this is");
  const std::string ctype = error_of(
      "{\"Shader\": {\"renderpass\": [\n  {\"type\": \"image\", \"code\": \"\",\n   \"inputs\": [{\"ctype\": \"hologram\", "
      "\"channel\": 0}]}]}}");
  EXPECT_NE(ctype.find("bad.json:3: Shader.renderpass[0].inputs[0].ctype: unknown input type 'hologram'"),
            std::string::npos)
      << ctype;
  EXPECT_NE(error_of("{\"Shader\": {\"renderpass\": [{\"type\": \"image\", \"inputs\": [{\"ctype\": \"keyboard\", "
                     "\"channel\": 4}]}]}}")
                .find("channel 4 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of("{\"Shader\": {\"renderpass\": [{\"type\": \"buffer\", \"name\": \"Buffer A\", \"outputs\": [{\"id\": 257}]},"
                     "{\"type\": \"buffer\", \"name\": \"Other\", \"outputs\": [{\"id\": 257}]}, {\"type\": \"image\"}]}}")
                .find("two passes write Buffer A"),
            std::string::npos);
  EXPECT_NE(error_of("{\"Shader\": {\"renderpass\": [{\"type\": \"buffer\", \"name\": \"Buffer A\"}]}}")
                .find("no Image pass"),
            std::string::npos);
  EXPECT_NE(error_of("{\"Shader\": {\"renderpass\": [{\"type\": \"cubemap\"}, {\"type\": \"cubemap\"}, {\"type\": \"image\"}]}}")
                .find("more than one cubemap pass"),
            std::string::npos);
  EXPECT_NE(error_of("{\"Shader\": {\"renderpass\": [{\"type\": \"image\", \"inputs\": [{\"ctype\": \"cubemap\", \"id\": 9, "
                     "\"channel\": 0}]}]}}")
                .find("a cubemap input without a src"),
            std::string::npos);
  EXPECT_NE(error_of("{\"Error\": \"Shader not found\"}").find("an error from the Shadertoy API"), std::string::npos);
}

// Cube A (type "cubemap") runs after the buffers and before the Image pass
// whatever the file's order; inputs name it by id 41, "4dX3Rr" or its
// previz file, and a cubemap of files by its src.
TEST(ProjectJson, CubeAPassAndCubemapInputs) {
  const ShaderProject p = load_shadertoy_json(R"({"Shader": {"renderpass": [
    {"type": "image", "code": "// i", "inputs": [
      {"id": 41, "ctype": "cubemap", "channel": 0},
      {"id": "4dX3Rr", "type": "cubemap", "channel": 1},
      {"id": 5, "ctype": "cubemap", "channel": 2, "src": "/media/previz/cubemap00.png"},
      {"id": 22, "ctype": "cubemap", "channel": 3, "src": "/media/a/sky.jpg"}]},
    {"type": "cubemap", "code": "// c", "outputs": [{"id": 41, "channel": 0}]},
    {"name": "Buffer A", "type": "buffer", "code": "// a", "outputs": [{"id": 257, "channel": 0}]}]}})",
                                              "c.json");
  ASSERT_EQ(p.passes.size(), 3u);
  EXPECT_EQ(p.passes[0].name, "Buffer A");
  EXPECT_EQ(p.passes[1].kind, PassKind::cube);
  EXPECT_EQ(p.passes[1].name, "Cube A");
  EXPECT_EQ(p.passes[1].output, kCubeA);
  EXPECT_EQ(p.passes[1].code, "// c");
  const auto& in = p.passes[2].inputs;
  for (int c = 0; c < 4; ++c) EXPECT_EQ(in[c].kind, InputKind::cubemap) << c;
  EXPECT_EQ(in[0].buffer, kCubeA);
  EXPECT_EQ(in[1].buffer, kCubeA);
  EXPECT_EQ(in[2].buffer, kCubeA);
  EXPECT_EQ(in[3].buffer, -1);
  EXPECT_EQ(in[3].src, "/media/a/sky.jpg");
}

TEST(EsCompat, RenamesDesktopKeywordsOnlyAsWords) {
  EXPECT_EQ(rename_desktop_keywords("float sample = buffer + shared2; // sample\n#include \"buffer.glsl\"\nvec3 precise;"),
            "float ms_es_sample = ms_es_buffer + shared2; // sample\n#include \"buffer.glsl\"\nvec3 ms_es_precise;");
  EXPECT_EQ(rename_desktop_keywords("/* patch\n */ x = 1e5; patch2"), "/* patch\n */ x = 1e5; patch2");
}

}  // namespace
}  // namespace ms
