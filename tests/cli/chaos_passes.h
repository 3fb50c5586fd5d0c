// A two-pass scene whose Buffer A is a chaotic map of its previous value,
// so a lost, repeated or foreign buffer state shows in every later frame:
// the fixture of the multipass sequence and checkpoint tests.
//
//   write_chaos_project(dir, 3, 64, 48);   // s.toml, a.glsl, img.glsl
//   run_marchstudio({"render", "s.toml", "--frames", "0..5", ...}, dir.path());
#pragma once
#include <string>

#include "run.h"

namespace ms::test {

// `loops` iterations of the map a frame: more slow a frame down, so a run
// can be killed half way. The image shows x in red and the frame count / 64
// in green.
inline void write_chaos_project(const TempDir& dir, int loops, int width, int height) {
  write_file(dir / "s.toml",
             "[scene]\nname = \"chaos\"\n[render]\nwidth = " + std::to_string(width) + "\nheight = " +
                 std::to_string(height) +
                 "\n[[passes]]\ntype = \"buffer\"\nbuffer = \"A\"\nfile = \"a.glsl\"\niChannel0 = { buffer = \"A\" }\n"
                 "[[passes]]\ntype = \"image\"\nfile = \"img.glsl\"\niChannel0 = { buffer = \"A\" }\n");
  write_file(dir / "a.glsl",
             "void mainImage(out vec4 o, in vec2 f) {\n"
             "  vec4 p = texelFetch(iChannel0, ivec2(f), 0);\n"
             "  float x = iFrame == 0 ? fract(f.x * 0.137 + f.y * 0.291) : p.x;\n"
             "  for (int i = 0; i < " + std::to_string(loops) + "; ++i) x = 3.9 * x * (1.0 - x);\n"
             "  o = vec4(x, p.y + 1.0, 0.0, 1.0);\n"
             "}\n");
  write_file(dir / "img.glsl",
             "void mainImage(out vec4 o, in vec2 f) { vec4 a = texelFetch(iChannel0, ivec2(f), 0); "
             "o = vec4(a.x, a.y / 64.0, 0.5, 1.0); }\n");
}

}  // namespace ms::test
