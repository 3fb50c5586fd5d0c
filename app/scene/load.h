// Scene files: read a .toml (docs/scene-format.md), validate every key and
// value, and return a Scene. Every problem is an ms::Error (Exit::bad_input)
// naming file:line and the dotted key, with a did-you-mean hint where one
// helps; nothing is silently clamped or ignored.
#pragma once
#include <filesystem>
#include <string_view>

#include "scene/overrides.h"
#include "scene/scene.h"

namespace ms {

// Read and validate the scene file at `toml_path`. Scene::file is the path as
// given; Scene::map_file is `scene.map` resolved against the file's folder.
// `overrides` (--set) change the parsed file before it is validated
// (scene/overrides.h); an error they cause names their flag.
Scene load_scene(const std::filesystem::path& toml_path, const SceneOverrides& overrides = {});

// The same from text already in memory (tests, fuzzing). `display_path`
// names the file in errors and anchors a relative `scene.map`; the map file
// must exist.
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& display_path,
                  const SceneOverrides& overrides = {});

}  // namespace ms
