#include "scene/project.h"

#include "core/error.h"

namespace ms {

const char* input_kind_name(InputKind k) {
  switch (k) {
    case InputKind::none: return "nothing";
    case InputKind::buffer: return "buffer";
    case InputKind::texture: return "texture";
    case InputKind::keyboard: return "keyboard";
    case InputKind::cubemap: return "cubemap";
    case InputKind::volume: return "volume";
    case InputKind::music: return "music";
    case InputKind::musicstream: return "musicstream";
    case InputKind::mic: return "mic";
    case InputKind::video: return "video";
    case InputKind::webcam: return "webcam";
  }
  return "?";
}

ChannelType channel_type(InputKind k) {
  return k == InputKind::cubemap ? ChannelType::cube : k == InputKind::volume ? ChannelType::tex3d : ChannelType::tex2d;
}

const char* glsl_sampler_type(ChannelType t) {
  return t == ChannelType::cube ? "samplerCube" : t == ChannelType::tex3d ? "sampler3D" : "sampler2D";
}

std::string buffer_letter(int buffer) { return std::string(1, static_cast<char>('A' + buffer)); }

void check_project(ShaderProject& p, const std::string& file, Unwritten unwritten) {
  if (p.passes.empty() || p.passes.back().kind != PassKind::image)
    fail_input("the shader has no Image pass", file, 0, {}, "a Shadertoy shader draws its picture in the Image pass");
  bool writes[4] = {false, false, false, false};
  bool cube = false;
  for (size_t i = 0; i < p.passes.size(); ++i) {
    const ProjectPass& pass = p.passes[i];
    if (pass.kind == PassKind::image && i + 1 != p.passes.size())
      fail_input("the shader has more than one Image pass", file, 0, pass.name);
    if (pass.kind == PassKind::cube) {
      if (cube) fail_input("the shader has more than one Cube A pass", file, 0, pass.name, "Shadertoy has one, Cube A");
      cube = true;
      continue;
    }
    if (pass.kind != PassKind::buffer) continue;
    if (pass.output < 0 || pass.output > 3)
      fail_input(pass.name + " writes no buffer A..D", file, 0, pass.name);
    if (writes[pass.output])
      fail_input("two passes write Buffer " + buffer_letter(pass.output), file, 0, pass.name,
                 "each buffer has one pass that draws it");
    writes[pass.output] = true;
  }
  // Shadertoy binds a buffer (or Cube A) that no pass writes as it stands
  // before frame 0, all zero: a warning here, an error in a scene's [[passes]].
  for (const ProjectPass& pass : p.passes)
    for (size_t c = 0; c < pass.inputs.size(); ++c) {
      const ProjectInput& in = pass.inputs[c];
      const std::string channel = pass.name + " iChannel" + std::to_string(c);
      if (in.kind == InputKind::buffer && (in.buffer < 0 || in.buffer > 3))
        fail_input(channel + " reads Buffer ?, which no pass writes", file, 0, pass.name + ".iChannel" + std::to_string(c));
      std::string what;
      if (in.kind == InputKind::buffer && !writes[in.buffer])
        what = channel + " reads Buffer " + buffer_letter(in.buffer) + ", which no pass writes";
      else if (in.kind == InputKind::cubemap && in.buffer == kCubeA && !cube)
        what = channel + " reads Cube A, which no pass writes";
      if (what.empty()) continue;
      if (unwritten == Unwritten::refuse)
        fail_input(what, file, 0, pass.name + ".iChannel" + std::to_string(c),
                   in.kind == InputKind::buffer ? "" : "add the cubemap pass (type \"cubemap\", mainCubemap)");
      p.warnings.push_back(what + ": it reads 0, an empty " +
                           (in.kind == InputKind::buffer ? std::string("buffer of the image's size") : "Cube A") +
                           ", as on Shadertoy");
    }
}

}  // namespace ms
