#include "scene/load_passes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/input_file.h"
#include "core/suggest.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kSettingsKeys[] = {"common", "media_dir", "missing_media", "mouse", "fps"};
constexpr std::string_view kPassKeys[] = {"type", "buffer", "file", "name", "iChannel0", "iChannel1", "iChannel2",
                                          "iChannel3"};
constexpr std::string_view kChannelKeys[] = {"buffer", "texture", "cubemap", "keyboard", "filter", "wrap", "vflip", "srgb"};
constexpr std::string_view kPassTypes[] = {"buffer", "image", "cubemap"};
constexpr std::string_view kFilters[] = {"nearest", "linear", "mipmap"};
constexpr std::string_view kWraps[] = {"clamp", "repeat"};
constexpr std::string_view kMissing[] = {"error", "noise", "black"};
constexpr std::string_view kBuffers[] = {"A", "B", "C", "D"};

fs::path relative_to(const fs::path& scene_file, const std::string& p) {
  return (scene_file.parent_path() / fs::path(p)).lexically_normal();
}

// Shadertoy's own media name ("/media/a/<hash>.png"): not a path here, but
// a file name looked up in the media directory when the passes are built
// (pipeline/project_passes.h), as a JSON's src is.
bool shadertoy_media_name(const std::string& src) { return src.rfind("/media/a/", 0) == 0; }

// A file a key names: relative to the scene, a readable regular file.
fs::path existing_file(const Reader& r, const toml::table& t, std::string_view path, std::string_view key,
                       const fs::path& scene_file) {
  std::string name;
  r.read(t, path, key, name);
  const std::string dotted = join_key(path, key);
  if (name.empty()) r.fail(Reader::line_of(t, key), dotted, quote(dotted) + " must not be empty");
  const fs::path f = relative_to(scene_file, name);
  if (const std::string why = input_file_problem(f); !why.empty())
    r.fail(Reader::line_of(t, key), dotted, quote(f.string()) + " " + why,
           why == "not found" ? quote(dotted) + " is relative to the scene file" : "");
  return f;
}

ProjectInput read_channel(const Reader& r, const toml::table& ch, const std::string& path, const fs::path& scene_file,
                          const ShadertoySettings& settings) {
  r.check_keys(ch, path, kChannelKeys);
  ProjectInput in;
  int kinds = 0;
  if (ch.contains("buffer")) {
    in.kind = InputKind::buffer;
    std::size_t b = 0;
    r.read_enum(ch, path, "buffer", kBuffers, b);
    in.buffer = static_cast<int>(b);
    ++kinds;
  }
  if (ch.contains("texture")) {
    in.kind = InputKind::texture;
    r.read(ch, path, "texture", in.src);
    in.sampler = Sampler{TexFilter::mipmap, TexWrap::repeat, true, false};  // Shadertoy's texture defaults
    const fs::path f = relative_to(scene_file, in.src);
    const std::string why = shadertoy_media_name(in.src) ? "" : input_file_problem(f);
    if (shadertoy_media_name(in.src)) {
      // found by name when the passes are built
    } else if (why.empty()) {
      in.file = f;
    } else if (settings.missing_media == MissingMedia::error || why != "not found")
      r.fail(Reader::line_of(ch, "texture"), join_key(path, "texture"), "texture " + quote(f.string()) + " " + why,
             why == "not found" ? "relative to the scene file; --missing-media noise|black stands in for it" : "");
    ++kinds;
  }
  if (ch.contains("cubemap")) {  // "A": the Cube A pass; else face 0's file or one equirectangular .exr/.hdr
    in.kind = InputKind::cubemap;
    r.read(ch, path, "cubemap", in.src);
    if (in.src == "A") in.buffer = kCubeA;
    else if (shadertoy_media_name(in.src)) {
      // found by name when the passes are built
    } else if (const fs::path f = relative_to(scene_file, in.src); input_file_problem(f).empty()) in.file = f;
    else if (settings.missing_media == MissingMedia::error || input_file_problem(f) != "not found")
      r.fail(Reader::line_of(ch, "cubemap"), join_key(path, "cubemap"),
             "cubemap " + quote(f.string()) + " " + input_file_problem(f),
             "relative to the scene file; \"A\" reads the Cube A pass; --missing-media noise|black stands in for it");
    ++kinds;
  }
  if (ch.contains("keyboard")) {
    bool on = false;
    r.read(ch, path, "keyboard", Range::any(), on);
    if (!on) r.fail(Reader::line_of(ch, "keyboard"), join_key(path, "keyboard"), "'keyboard' can only be true");
    in.kind = InputKind::keyboard;
    ++kinds;
  }
  if (kinds != 1)
    r.fail(Reader::line_of(ch), path, quote(path) + " needs exactly one of buffer, texture, cubemap or keyboard",
           "e.g. " + path + " = { buffer = \"A\" }");
  if (ch.contains("filter")) {
    std::size_t f = 0;
    r.read_enum(ch, path, "filter", kFilters, f);
    in.sampler.filter = static_cast<TexFilter>(f);
  }
  if (ch.contains("wrap")) {
    std::size_t w = 0;
    r.read_enum(ch, path, "wrap", kWraps, w);
    in.sampler.wrap = static_cast<TexWrap>(w);
  }
  r.read(ch, path, "vflip", Range::any(), in.sampler.vflip);
  r.read(ch, path, "srgb", Range::any(), in.sampler.srgb);
  return in;
}

}  // namespace

void read_shadertoy_settings(const Reader& r, const toml::table& root, const fs::path& scene_file,
                             ShadertoySettings& out) {
  const toml::table* t = r.table(root, {}, "shadertoy");
  if (!t) return;
  r.check_keys(*t, "shadertoy", kSettingsKeys);
  if (t->contains("common")) out.common_file = existing_file(r, *t, "shadertoy", "common", scene_file);
  if (t->contains("media_dir")) {
    std::string dir;
    r.read(*t, "shadertoy", "media_dir", dir);
    out.media_dir = relative_to(scene_file, dir);
    std::error_code ec;
    if (!fs::is_directory(out.media_dir, ec))
      r.fail(Reader::line_of(*t, "media_dir"), "shadertoy.media_dir",
             "media directory " + quote(out.media_dir.string()) + " is not a directory");
  }
  if (t->contains("missing_media")) {
    std::size_t m = 0;
    r.read_enum(*t, "shadertoy", "missing_media", kMissing, m);
    out.missing_media = static_cast<MissingMedia>(m);
  }
  if (const toml::node* m = t->get("mouse")) {
    const toml::array* a = m->as_array();
    if (!a || a->size() != 4)
      r.fail(*m, "shadertoy.mouse", "'shadertoy.mouse' must be 4 numbers", "iMouse: x, y, click x, click y in pixels");
    for (size_t i = 0; i < 4; ++i) {
      const std::optional<double> v = (*a)[i].value<double>();
      if (!v || !std::isfinite(*v) || std::abs(*v) > 1e9)
        r.fail((*a)[i], "shadertoy.mouse", "'shadertoy.mouse' must be 4 finite numbers");
      out.mouse[i] = static_cast<float>(*v);
    }
  }
  float fps = static_cast<float>(out.fps);
  if (r.read(*t, "shadertoy", "fps", Range::open(0, 1000), fps)) out.fps = fps;
}

std::shared_ptr<const ShaderProject> read_passes(const Reader& r, const toml::table& root, const fs::path& scene_file,
                                                 const ShadertoySettings& settings) {
  const std::vector<const toml::table*> tables = r.tables(root, {}, "passes");
  if (tables.empty()) return nullptr;
  auto p = std::make_shared<ShaderProject>();
  p->origin = scene_file;
  p->name = scene_file.stem().string();
  if (!settings.common_file.empty()) {
    p->common_file = settings.common_file;
    p->common_where = settings.common_file.string();
  }
  std::vector<ProjectPass> buffers;
  std::vector<ProjectPass> images;
  for (size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string path = "passes[" + std::to_string(i) + "]";
    r.check_keys(t, path, kPassKeys);
    ProjectPass pass;
    std::size_t type = 1;
    if (!t.contains("type"))
      r.fail(Reader::line_of(t), path, "missing required key " + quote(path + ".type"), "type = \"buffer\" or \"image\"");
    r.read_enum(t, path, "type", kPassTypes, type);
    pass.kind = type == 0 ? PassKind::buffer : type == 2 ? PassKind::cube : PassKind::image;
    if (pass.kind == PassKind::cube) {  // Cube A: mainCubemap, after the buffers
      if (t.contains("buffer")) r.fail(Reader::line_of(t, "buffer"), path + ".buffer", "a cubemap pass writes Cube A, not a buffer");
      pass.output = kCubeA;
      pass.name = "Cube A";
    } else if (pass.kind == PassKind::buffer) {
      if (!t.contains("buffer"))
        r.fail(Reader::line_of(t), path, "a buffer pass needs " + quote(path + ".buffer"), "buffer = \"A\" (A..D)");
      std::size_t b = 0;
      r.read_enum(t, path, "buffer", kBuffers, b);
      pass.output = static_cast<int>(b);
      pass.name = "Buffer " + buffer_letter(pass.output);
    } else {
      if (t.contains("buffer"))
        r.fail(Reader::line_of(t, "buffer"), path + ".buffer", "an image pass writes the image, not a buffer");
      pass.name = "Image";
    }
    r.read(t, path, "name", pass.name);
    if (!t.contains("file")) r.fail(Reader::line_of(t), path, "missing required key " + quote(path + ".file"));
    pass.file = existing_file(r, t, path, "file", scene_file);
    pass.where = pass.file.string();
    for (int c = 0; c < 4; ++c) {
      const std::string key = "iChannel" + std::to_string(c);
      if (!t.contains(key)) continue;
      const toml::table* ch = t.get(key)->as_table();
      if (!ch) r.fail(*t.get(key), path + "." + key, quote(path + "." + key) + " must be a table",
                      key + " = { buffer = \"A\" }");
      pass.inputs[c] = read_channel(r, *ch, path + "." + key, scene_file, settings);
    }
    for (const ProjectPass& other : buffers)
      if (pass.kind == PassKind::buffer && other.output == pass.output)
        r.fail(Reader::line_of(t, "buffer"), path + ".buffer",
               "two passes write Buffer " + buffer_letter(pass.output), "each buffer has one pass that draws it");
    if (pass.kind == PassKind::image && !images.empty())
      r.fail(Reader::line_of(t, "type"), path + ".type", "more than one image pass");
    if (pass.kind == PassKind::cube)
      for (const ProjectPass& other : buffers)
        if (other.kind == PassKind::cube) r.fail(Reader::line_of(t, "type"), path + ".type", "more than one cubemap pass");
    (pass.kind == PassKind::image ? images : buffers).push_back(std::move(pass));
  }
  if (images.empty())
    r.fail(Reader::line_of(*tables.back()), "passes", "the [[passes]] have no image pass",
           "one [[passes]] table with type = \"image\" draws the picture");
  std::stable_sort(buffers.begin(), buffers.end(),
                   [](const ProjectPass& a, const ProjectPass& b) { return a.output < b.output; });
  p->passes = std::move(buffers);
  p->passes.push_back(std::move(images.front()));
  // Buffer inputs must name a buffer some pass writes.
  for (size_t i = 0; i < tables.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const std::string key = "iChannel" + std::to_string(c);
      const toml::table* ch = tables[i]->contains(key) ? tables[i]->get(key)->as_table() : nullptr;
      if (!ch || !ch->contains("buffer")) continue;
      const std::string letter = ch->get("buffer")->value_or(std::string());
      bool written = false;
      for (const ProjectPass& pass : p->passes) written = written || (pass.kind == PassKind::buffer &&
                                                                         buffer_letter(pass.output) == letter);
      if (!written)
        r.fail(Reader::line_of(*ch, "buffer"), "passes[" + std::to_string(i) + "]." + key + ".buffer",
               "Buffer " + letter + " is read here, but no pass writes it");
    }
  check_project(*p, scene_file.string(), Unwritten::refuse);  // e.g. a cubemap = "A" with no cubemap pass
  return p;
}

}  // namespace ms
