// A Shadertoy-style program as data: a Common source, buffer passes A..D
// and the Image pass, each with up to four typed inputs. Loaded from
// Shadertoy's JSON (importers/project_json.h), a scene's [[passes]]
// (scene/load_passes.h) or a bare .glsl (one Image pass); run by
// render/graph.h. No GL and no file reading here.
//
//   ShaderProject p = load_shadertoy_json(text, "x.json");
//   for (const ProjectPass& pass : p.passes) ...   // in Shadertoy's order
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace ms {

// Sampler state of one input, Shadertoy's names and defaults (a texture's:
// mipmap, repeat, vflip; a buffer's: linear, clamp).
enum class TexFilter { nearest, linear, mipmap };
enum class TexWrap { clamp, repeat, mirror };  // mirror: the VS Code extension's "Mirror" (importers/vscode.h)
struct Sampler {
  TexFilter filter = TexFilter::linear;
  TexWrap wrap = TexWrap::clamp;
  bool vflip = false;  // textures only: row 0 of the file at the top of uv (Shadertoy's default true)
  bool srgb = false;   // textures only: decode sRGB to linear when sampled
};

// What a channel reads. Shadertoy's ctypes; the ones marchstudio does not
// run (the live devices webcam and mic) are refused where the project is
// loaded, never bound as black. Video is decoded through ffmpeg
// (io/video_input.h), music through libsndfile (io/audio.h), a cubemap is
// six face files or one equirectangular image (io/cube_faces.h) or the
// Cube A pass (docs/shadertoy.md#cubemaps).
enum class InputKind { none, buffer, texture, keyboard, cubemap, volume, music, musicstream, mic, video, webcam };

const char* input_kind_name(InputKind k);

// The sampler type a channel is declared with follows what is bound to it
// (buffers, textures, the keyboard and an empty channel are 2D).
enum class ChannelType { tex2d, cube, tex3d };
ChannelType channel_type(InputKind k);
const char* glsl_sampler_type(ChannelType t);  // "sampler2D", "samplerCube", "sampler3D"

struct ProjectInput {
  InputKind kind = InputKind::none;
  int buffer = -1;   // buffer: 0..3 for A..D; cubemap: kCubeA when it reads the Cube A pass
  std::string src;   // texture, volume, cubemap: as given ("/media/a/<hash>.png", or a path from a scene file)
  std::filesystem::path file;  // texture: the file found for src (load_media resolves it)
  Sampler sampler;
  std::string uniform;  // glslViewer: the sampler's own name (u_tex0, u_buffer1); empty: iChannelN
};

// cube: Shadertoy's Cube A, mainCubemap() into six faces, run after the
// buffers and before the Image pass.
enum class PassKind { buffer, cube, image };

// The output of the Cube A pass, and a cubemap input's `buffer` reading it.
inline constexpr int kCubeA = 4;

struct ProjectPass {
  PassKind kind = PassKind::image;
  int output = -1;               // buffer passes: the buffer written, 0..3 for A..D; kCubeA for Cube A
  std::string name;              // "Buffer A", "Image"
  std::string code;              // the GLSL, when it came inline (JSON)
  std::filesystem::path file;    // or the file it is in (a scene's [[passes]], a bare .glsl)
  std::string where;             // how errors name it: "x.json (Buffer A)" or the file's display path
  std::array<ProjectInput, 4> inputs{};
  std::string define;            // glslViewer: the pass's #define (BUFFER_0, DOUBLE_BUFFER_1); empty for main
};

struct ShaderProject {
  std::string name;                  // info.name, or the file stem
  std::filesystem::path origin;      // the file it was loaded from (JSON, TOML or GLSL)
  std::string common;                // the Common tab, inline, or
  std::filesystem::path common_file; // in a file
  std::string common_where;          // its name in errors
  // Buffer passes in the order Shadertoy runs them (A, B, C, D), then
  // Cube A, then the Image pass, last.
  std::vector<ProjectPass> passes;
  bool glslviewer = false;           // a glslViewer file (importers/glslviewer.h): main(), gl_FragColor, u_* uniforms
  bool has_sound = false;            // a Sound pass was present and is not run (it never changes the image)
  std::vector<std::string> warnings; // for the caller to print: "x.json holds 2 shaders; rendering the first"

  const ProjectPass& image() const { return passes.back(); }
  bool stateful() const { return passes.size() > 1; }  // buffers carry state from frame to frame
};

// What stands in for a texture that is not in the media directory:
// nothing (an error naming the pass, channel and src), generated noise or
// black (each with a warning).
enum class MissingMedia { error, noise, black };

// A glslViewer texture from the command line: u_tex0.. by order, or named.
struct NamedTexture {
  std::string name;             // the sampler2D it binds, e.g. u_tex0
  std::filesystem::path file;
};

// Shadertoy settings of a scene file's [shadertoy] table or the flags.
struct ShadertoySettings {
  std::filesystem::path media_dir;        // where "/media/a/<hash>.png" is looked up by file name
  std::filesystem::path media_dir_flag;   // --media-dir: also a directory media may be read from (preprocess/confine.h)
  MissingMedia missing_media = MissingMedia::error;
  float mouse[4] = {0, 0, 0, 0};          // iMouse, Shadertoy's semantics
  double fps = 60.0;                      // a still of a stateful shader runs round(time * fps) + 1 frames
  std::filesystem::path common_file;      // [[passes]]: the Common source
  std::vector<NamedTexture> textures;     // --texture: a glslViewer shader's u_tex0.. (importers/glslviewer.h)
};

// "A".."D" for 0..3.
std::string buffer_letter(int buffer);

// What an input of a buffer (or Cube A) that no pass writes gets: refused
// (a scene's [[passes]]), or bound as Shadertoy binds it, all zero, with a
// warning in p.warnings (--strict makes it an error).
enum class Unwritten { refuse, warn };

// Checks what a loader built: exactly one Image pass and it is last, each
// buffer written by at most one pass, buffer inputs naming a buffer A..D,
// at most one Cube A pass; inputs of a buffer or Cube A that no pass writes
// as `unwritten` says. Throws bad_input naming `file` and the pass.
void check_project(ShaderProject& p, const std::string& file, Unwritten unwritten = Unwritten::warn);

}  // namespace ms
