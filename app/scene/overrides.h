// Scene overrides: `--set key=value` applied to a scene file's parsed TOML
// before it is validated, so every check of scene/load.cpp (types, ranges,
// unknown keys with did-you-mean, NaN) applies to an override exactly as to
// the file, and a render with --set equals one of the edited file.
//
//   SceneOverride o;                       // --set materials.ball.color=[1,0,0]
//   o.flag = "--set materials.ball.color";
//   o.path = {{"materials"}, {"ball"}, {"color"}};
//   o.value.push_back(toml::array{1, 0, 0});
//   Scene s = load_scene("scenes/seed.toml", {o});   // scene/load.h
//
// A path walks tables by key, creating a table that is missing (the schema
// then judges it: `quality.max_steps` on a file with no [quality] works,
// `camear.fov` is an unknown key 'camear'). In an array of tables a step is
// an entry: by index (`lights[0]`, or `lights.0`) or, by name, the entry
// whose `name` is that word (`materials.ball`). The last step replaces or
// adds the value; a value array's element can be replaced by index
// (`camera.position[1]`). cli/override_flags.h parses the flags.
//
// An override beats the file's [[animation]] too: a track animating an
// overridden value (or one inside or around it) is dropped, so the set
// value holds at every time, and -v says so (Scene::notes).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/error.h"
#include "scene/scene.h"

namespace ms {

struct KeyStep {
  std::string key;         // a key, or an entry's name; empty for an index step
  std::size_t index = 0;   // an index step: the entry (or element) number
  bool by_index = false;
};

struct SceneOverride {
  std::string flag;            // "--set camera.fov": names the override in every error
  std::vector<KeyStep> path;   // at least one step
  toml::array value;           // exactly one element: the value (an array keeps any TOML node by value)
};

using SceneOverrides = std::vector<SceneOverride>;

// Applies each override in order (a later one wins). Returns, for each, the
// dotted key the scene's checks name it by ("materials[1].color"), for
// blame_override(). A path that cannot be applied (a missing entry, a step
// into a number) is an ms::Error naming the flag.
std::vector<std::string> apply_overrides(toml::table& root, const SceneOverrides& overrides);

// Drops each track of scene.animation whose target an override set (the
// same value, a part of it or a table holding it; `keys` as
// apply_overrides() returned them), with a note in scene.notes.
void drop_overridden_tracks(Scene& scene, const SceneOverrides& overrides, const std::vector<std::string>& keys);

// An error of the scene's validation at or under an overridden key is that
// override's fault: the same message, located at its flag rather than at a
// line of the file. Others are returned unchanged.
ErrorInfo blame_override(ErrorInfo e, const SceneOverrides& overrides, const std::vector<std::string>& keys);

}  // namespace ms
