#include "pipeline/project_passes.h"

#include <algorithm>
#include <map>
#include <memory>
#include <system_error>
#include <tuple>

#include "core/error.h"
#include "io/audio.h"
#include "io/image_io.h"
#include "io/input_file.h"
#include "io/video_input.h"
#include "pipeline/cube_input.h"
#include "preprocess/confine.h"
#include "importers/glslviewer.h"
#include "importers/shadertoy.h"
#include "importers/shadertoy_media.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Where media may come from, and how errors name the input.
struct MediaPlace {
  const ShadertoySettings& s;
  std::vector<fs::path> roots;  // preprocess/confine.h's media_roots
  std::string origin;           // the file errors name
};

// The file for a medium: a path the project gave (already resolved), or
// the src's file name in the media directory; empty when it is not there.
// Either must lie inside the media roots (a --texture file, named on the
// command line, is the user's own): a symlink to elsewhere is refused
// whether or not its target exists. `what`: "texture '<src>'".
fs::path find_media(const ProjectInput& in, const MediaPlace& m, const std::string& where, const std::string& what) {
  fs::path f = in.file;
  if (f.empty()) {
    const fs::path name = fs::path(in.src).filename();
    if (name.empty() || m.s.media_dir.empty()) return {};
    f = m.s.media_dir / name;
  }
  const bool named_by_user = std::any_of(m.s.textures.begin(), m.s.textures.end(),
                                         [&](const NamedTexture& t) { return t.file == in.file && !in.file.empty(); });
  if (!named_by_user) confine_media(f, m.roots, where + ": " + what, m.origin, where);
  return input_file_problem(f).empty() ? f : fs::path{};
}

// PCG32 (O'Neill): a fixed, documented sequence on every platform.
struct Pcg {
  std::uint64_t state = 0x853c49e6748fea9bull;
  std::uint32_t next() {
    const std::uint64_t old = state;
    state = old * 6364136223846793005ull + 1442695040888963407ull;
    const std::uint32_t x = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const std::uint32_t r = static_cast<std::uint32_t>(old >> 59u);
    return (x >> r) | (x << ((-r) & 31u));
  }
};

}  // namespace

Image media_standin(const std::string& src, MissingMedia kind) {
  Image img;
  img.channels = {"R", "G", "B", "A"};
  if (kind == MissingMedia::black) {
    img.width = img.height = 1;
    img.pixels = {0, 0, 0, 1};
    return img;
  }
  const ShadertoyMedia* m = find_shadertoy_media(src);
  img.width = img.height = m && m->noise_size > 0 ? m->noise_size : 256;
  Pcg rng;
  img.pixels.resize(static_cast<size_t>(img.width) * img.height * 4);
  for (float& v : img.pixels) v = static_cast<float>(rng.next() >> 24) / 255.0f;  // 8-bit levels, as a PNG's
  return img;
}

std::uint8_t volume_noise_byte(int x, int y, int z, int c, int size) {
  const std::uint32_t v = static_cast<std::uint32_t>(x + size * (y + size * z));
  const std::uint32_t state = v * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return static_cast<std::uint8_t>(((word >> 22u) ^ word) >> (8 * c));
}

Volume volume_standin(const ShadertoyMedia& m, MissingMedia kind) {
  Volume v;
  v.channels = m.single_channel ? 1 : 4;
  if (kind == MissingMedia::black) {
    v.size = 1;
    v.voxels.assign(static_cast<size_t>(v.channels), 0);
    if (v.channels == 4) v.voxels[3] = 255;
    return v;
  }
  v.size = m.noise_size;
  v.voxels.resize(static_cast<size_t>(v.size) * v.size * v.size * v.channels);
  size_t i = 0;
  for (int z = 0; z < v.size; ++z)
    for (int y = 0; y < v.size; ++y)
      for (int x = 0; x < v.size; ++x)
        for (int c = 0; c < v.channels; ++c) v.voxels[i++] = volume_noise_byte(x, y, z, c, v.size);
  return v;
}

namespace {

// One project's media, each file read or decoded once however many
// channels use it, and where missing ones are looked for.
struct ProjectMedia {
  const MediaPlace& place;
  std::vector<std::string>& warnings;
  std::map<fs::path, std::shared_ptr<const Image>> decoded;
  std::map<std::string_view, std::shared_ptr<const Volume>> volumes;  // by hash: one upload per volume
  std::map<fs::path, std::shared_ptr<const AudioClip>> clips;
  std::map<std::tuple<fs::path, bool, bool>, std::shared_ptr<VideoStream>> videos;  // one decoder per file, vflip, sRGB
  std::map<fs::path, std::shared_ptr<const CubeFaces>> cubes;
};

// A missing medium under --missing-media error: the one-line refusal.
[[noreturn]] void missing_media(const ProjectMedia& m, const std::string& where, const std::string& what,
                                const std::string& otherwise) {
  const ShadertoySettings& s = m.place.s;
  fail_input(where + ": " + what + " is not in the media directory", m.place.origin, 0, where,
             (s.media_dir.empty() ? std::string("no media directory") : "looked in " + s.media_dir.string()) +
                 "; give --media-dir DIR, or --missing-media noise|black to " + otherwise);
}

void bind_texture(const ProjectInput& in, const std::string& where, ProjectMedia& m, GraphInput& g) {
  const ShadertoySettings& s = m.place.s;
  const ShadertoyMedia* known = find_shadertoy_media(in.src);
  g.single_channel = known && known->single_channel;
  const std::string what = "texture '" + in.src + "'";
  const fs::path f = find_media(in, m.place, where, what);
  if (f.empty()) {
    if (s.missing_media == MissingMedia::error) missing_media(m, where, what, "stand in for it");
    const bool noise = s.missing_media == MissingMedia::noise;
    m.warnings.push_back(where + ": " + what + " is missing; " +
                         (noise ? "generated noise stands in (not Shadertoy's pixels)" : "black stands in"));
    g.image = std::make_shared<const Image>(media_standin(in.src, s.missing_media));
    return;
  }
  auto& img = m.decoded[f];
  if (!img) img = std::make_shared<const Image>(read_image(f, AlphaMode::straight));
  g.image = img;
  g.file = f.string();
  g.eight_bit = !is_float_image_name(f);
}

// Volumes are never read from files: a known one is stood in for.
void bind_volume(const ProjectInput& in, const std::string& where, ProjectMedia& m, GraphInput& g) {
  const ShadertoySettings& s = m.place.s;
  const ShadertoyMedia* known = find_shadertoy_media(in.src);
  if (!known || !known->volume)
    fail_input(where + ": volume '" + in.src + "' is not one of Shadertoy's volumes", m.place.origin, 0, where,
               "marchstudio stands in for Gray Noise 3D and RGBA Noise 3D, by their /media/a/<hash>.bin");
  const std::string what = where + ": volume '" + in.src + "' (" + std::string(known->name) + ")";
  if (s.missing_media == MissingMedia::error)
    fail_input(what + " is not read from files", m.place.origin, 0, where,
               "give --missing-media noise for a generated 32^3 stand-in (not Shadertoy's voxels), or "
               "--missing-media black");
  const bool noise = s.missing_media == MissingMedia::noise;
  m.warnings.push_back(what + ": " + (noise ? "generated noise stands in (not Shadertoy's voxels)" : "black stands in"));
  auto& vol = m.volumes[known->hash];
  if (!vol) vol = std::make_shared<const Volume>(volume_standin(*known, s.missing_media));
  g.volume = vol;
}

// Found like a texture; missing: an error, or (a warning) the channel as
// Shadertoy has it before the audio loads: no clip, nothing bound.
void bind_audio(const ProjectInput& in, const std::string& where, ProjectMedia& m, GraphInput& g) {
  const std::string what = "audio '" + in.src + "'";
  const fs::path f = find_media(in, m.place, where, what);
  if (f.empty()) {
    if (m.place.s.missing_media == MissingMedia::error) missing_media(m, where, what, "read it as not loaded");
    m.warnings.push_back(where + ": " + what + " is missing; it reads as Shadertoy's audio before it loads: 0 in both rows");
    return;
  }
  auto& clip = m.clips[f];
  if (!clip) clip = std::make_shared<const AudioClip>(read_audio(f));
  g.audio = clip;
}

// Found like a texture; missing: an error, or the texture's stand-in with a warning.
void bind_video(const ProjectInput& in, const std::string& where, ProjectMedia& m, GraphInput& g) {
  const ShadertoySettings& s = m.place.s;
  const std::string what = "video '" + in.src + "'";
  const fs::path f = find_media(in, m.place, where, what);
  if (f.empty()) {
    if (s.missing_media == MissingMedia::error) missing_media(m, where, what, "stand in for it");
    const bool noise = s.missing_media == MissingMedia::noise;
    m.warnings.push_back(where + ": " + what + " is missing; " +
                         (noise ? "a still of generated noise stands in" : "black stands in"));
    g.kind = InputKind::texture;  // a still image, bound as a texture is
    g.image = std::make_shared<const Image>(media_standin(in.src, s.missing_media));
    return;
  }
  auto& v = m.videos[{f, in.sampler.vflip, in.sampler.srgb}];
  if (!v) v = open_video(f, where);  // ffmpeg missing, a file it cannot decode: one line
  g.video = v;
}

// Channel `in` of a pass as the graph binds it, its media found and read.
GraphInput bind_input(const ProjectInput& in, const std::string& where, ProjectMedia& m) {
  GraphInput g;
  g.kind = in.kind;
  g.buffer = in.buffer;
  g.sampler = in.sampler;
  g.uniform = in.uniform;
  switch (in.kind) {
    case InputKind::none:
    case InputKind::buffer:
    case InputKind::keyboard:
      break;
    case InputKind::cubemap:  // Cube A, six face files or one equirectangular image (pipeline/cube_input.h)
      if (in.buffer != kCubeA)
        g.cube = load_cube_input(in, m.place.s, m.place.roots, where, m.place.origin, m.warnings, m.cubes);
      break;
    case InputKind::texture:
      bind_texture(in, where, m, g);
      break;
    case InputKind::volume:
      bind_volume(in, where, m, g);
      break;
    case InputKind::music:
    case InputKind::musicstream:
      bind_audio(in, where, m, g);
      break;
    case InputKind::video:
      bind_video(in, where, m, g);
      break;
    case InputKind::mic:
    case InputKind::webcam:
      // A live device has no meaning for an offline, reproducible render.
      fail_input(where + " reads a " + std::string(input_kind_name(in.kind)) +
                     " input, a live device that an offline render cannot have",
                 m.place.origin, 0, where, "bind a music or video file instead (docs/shadertoy.md#support)");
    default:
      fail_input(where + " reads a " + std::string(input_kind_name(in.kind)) + " input, which marchstudio does not run yet",
                 m.place.origin, 0, where, "docs/shadertoy.md lists what is supported");
  }
  return g;
}

// --uniform: a name may be declared in any pass (each pass that declares it gets the value).
void apply_uniforms(std::vector<PassSource>& passes, const std::vector<UniformValue>& uniforms) {
  if (uniforms.empty()) return;
  std::vector<bool> found(uniforms.size(), false);
  std::vector<SceneParam> declared;
  for (PassSource& ps : passes) {
    const std::vector<bool> here = set_uniform_defaults(ps.source.text, uniforms);
    for (size_t i = 0; i < found.size(); ++i) found[i] = found[i] || here[i];
    for (SceneParam& d : parse_scene_params(ps.source.text)) declared.push_back(std::move(d));
  }
  check_uniforms_found(uniforms, found, declared);
}

}  // namespace

std::vector<PassSource> shadertoy_passes(const ShaderProject& project, const ShadertoySettings& settings,
                                         const AssembleOptions& opts, const fs::path& scene_file,
                                         std::vector<std::string>& warnings) {
  ShaderProject p = project;
  ShadertoySettings s = settings;
  std::error_code ec;
  if (s.media_dir.empty())  // the scene's folder, as render's loader defaults it (the viewer's too)
    s.media_dir = fs::absolute(scene_file.empty() ? p.origin : scene_file, ec).parent_path();
  bind_glslviewer_textures(p, s.textures, warnings);  // --texture: glslViewer's u_tex0..
  const std::string origin = display_path(scene_file.empty() ? p.origin : scene_file);
  warnings.insert(warnings.end(), p.warnings.begin(), p.warnings.end());
  const fs::path scene = scene_file.empty() ? p.origin : scene_file;
  const MediaPlace place{s, media_roots(scene, s.media_dir_flag, opts.allow_include), origin};
  ProjectMedia media{place, warnings, {}, {}, {}, {}, {}};
  std::vector<PassSource> out;
  for (size_t i = 0; i < p.passes.size(); ++i) {
    const ProjectPass& pass = p.passes[i];
    PassSource ps;
    ps.name = pass.name;
    ps.uniforms = p.glslviewer ? PassUniforms::glslviewer : PassUniforms::shadertoy;
    ps.output = pass.kind == PassKind::image ? -1 : pass.output;  // kCubeA for Cube A
    for (size_t c = 0; c < 4; ++c) {
      const ProjectInput& in = pass.inputs[c];
      const std::string where = pass.name + " " + (in.uniform.empty() ? "iChannel" + std::to_string(c) : in.uniform);
      ps.inputs[c] = bind_input(in, where, media);
    }
    ps.source = assemble_shadertoy_pass(p, i, opts, scene_file);
    out.push_back(std::move(ps));
  }
  apply_uniforms(out, opts.uniforms);
  return out;
}

}  // namespace ms
