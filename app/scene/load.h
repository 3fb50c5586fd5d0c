// Scene files: read a .toml (docs/scene-format.md), validate every key and
// value, and return a Scene. Every problem is an ms::Error (Exit::bad_input)
// naming file:line and the dotted key, with a did-you-mean hint where one
// helps; nothing is silently clamped or ignored.
#pragma once
#include <filesystem>
#include <string_view>
#include <vector>

#include "scene/overrides.h"
#include "scene/scene.h"

namespace ms {

// Read and validate the scene file at `toml_path`. Scene::file is the path as
// given; Scene::map_file is `scene.map` resolved against the file's folder.
// `overrides` (--set) change the parsed file before it is validated
// (scene/overrides.h); an error they cause names their flag. A graph file
// is read only from the scene file's folder and `roots` (the include
// roots: shader/assemble.h's include_roots()), judged where its symlinks
// lead.
Scene load_scene(const std::filesystem::path& toml_path, const SceneOverrides& overrides = {},
                 const std::vector<std::filesystem::path>& roots = {});

// The same from text already in memory (tests, fuzzing). `display_path`
// names the file in errors and anchors a relative `scene.map`; the map file
// must exist.
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& display_path,
                  const SceneOverrides& overrides = {}, const std::vector<std::filesystem::path>& roots = {});

}  // namespace ms
