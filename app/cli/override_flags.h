// --set key=value and --uniform NAME=VALUE, parsed once into typed values:
// scene overrides (scene/overrides.h), applied to the scene file before it
// is validated, and uniform values (shader/scene_params.h), made the
// initializers of the scene's ranged uniforms. Every subcommand that loads
// a scene takes both (render, sequences, bench, sweep, view).
//
//   Overrides ov;
//   add_override_flags(cmd, ov);                      // at flag set-up
//   load_input_scene(input, disable, opts, preset, ov.set); // pipeline/input.h
//   opts.uniforms = ov.uniforms;                      // AssembleOptions
#pragma once
#include <string>
#include <vector>

#include "scene/overrides.h"
#include "shader/scene_params.h"

namespace CLI {
class App;
}

namespace ms {

struct Overrides {
  SceneOverrides set;                 // in flag order: a later one wins
  std::vector<UniformValue> uniforms;
  std::vector<std::string> as_given;  // "--set camera.fov=30", ...: for reports that record the command
};

// Both flags, repeatable, each parsed as it is read (bad input throws then).
void add_override_flags(CLI::App* cmd, Overrides& out);

// "camera.fov=30", "materials.ball.color=[1,0,0]", "lights[0].intensity=3",
// "quality.preset=fast": the key as a path, the value as TOML (a bare word
// such as fast is a string). Throws bad_input naming --set.
SceneOverride parse_set_flag(const std::string& text);

// "uTwist=1.25", "uTint=[1,0.8,0.6]" (or 1,0.8,0.6). Throws bad_input
// naming --uniform.
UniformValue parse_uniform_flag(const std::string& text);

}  // namespace ms
