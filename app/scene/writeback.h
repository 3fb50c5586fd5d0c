// Writing values back into a scene's TOML file TEXTUALLY: only the text of
// the changed values is replaced, so comments, key order, spacing and the
// way every other number is written survive. Absent keys are added at the
// end of their table. The viewer uses it for "write camera" and "write the
// panel's values"; nothing here touches GL.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace ms {

// One value to set. `table` is a top-level table ("camera"); `index` >= 0
// selects an entry of an array of tables ("lights", 0), -1 a plain table.
// `value` is TOML text, e.g. from toml_vec3().
struct TomlEdit {
  std::string table;
  int index = -1;
  std::string key;
  std::string value;
};

// Values as TOML text. Floats use the shortest digits that read back as the
// same 32-bit float and always have a '.' or an exponent ("1.0", "0.35").
std::string toml_float(float v);
std::string toml_int(int v);
std::string toml_bool(bool v);
std::string toml_vec3(glm::vec3 v);
std::string toml_string(const std::string& s);

// Apply `edits` in order to the TOML `text`. An existing key keeps its place
// and any comment after it, and its text when the value is the same (`fov =
// 50` stays, though the edit says 50.0); an absent key goes on a new line after the
// table's last key (or inside the braces of an inline table); an absent
// plain table is appended. Throws bad_input, located in `display_name`, when
// the text is not TOML, an array entry does not exist, or the result would
// not parse.
std::string apply_toml_edits(std::string_view text, const std::vector<TomlEdit>& edits,
                             const std::string& display_name);

// Called with the new text before it replaces the file; throw to cancel.
using TomlCheck = std::function<void(const std::string& new_text)>;

// Read `file`, apply the edits, run `check` (if any), then replace the file
// atomically: a temporary in the same directory (same permissions), fsync,
// rename. On any failure the file is untouched and no temporary is left.
void write_toml_edits(const std::filesystem::path& file, const std::vector<TomlEdit>& edits,
                      const TomlCheck& check = {});

// [camera] position, target, up and fov.
std::vector<TomlEdit> camera_edits(const Camera& cam);

// Every value the viewer's panel can change (lights, materials, quality,
// sky, render.exposure) that differs between `before` (the scene as loaded
// from the file) and `after`. Lights keep their type; keys that the loader
// would reject for an entry (direction on a point light, color2 on a plain
// material) are never produced.
std::vector<TomlEdit> scene_value_edits(const Scene& before, const Scene& after);

}  // namespace ms
