// A graph file named on its own (`render part.json`, docs/scene-graph.md):
// told from Shadertoy JSON by its content, and made into a default scene
// in this one place, so render, view, mesh, bench and info see the same.
//
//   if (json_input_kind(text, "part.json") == JsonInput::graph) scene = graph_alone_scene("part.json");
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace ms {

enum class JsonInput { graph, shadertoy };

// What a JSON text holds, by its top level: an object with "root" is a
// graph; an array, or an object with "Shader", "renderpass" or "Error",
// Shadertoy's. Anything else throws one line naming both forms (exit 2).
JsonInput json_input_kind(std::string_view text, const std::string& display);

// Whether `file` holds a scene graph, by its content (a .json name may be
// Shadertoy's, a download may be named .glsl, and an image never starts
// as JSON does): its first bytes, then, for JSON, json_input_kind(), which
// throws for JSON that is neither. False for a file that is missing or not
// regular, whose reader says why.
bool is_graph_file(const std::filesystem::path& file);

// The scene around the graph in `file`: the graph as `[scene] graph` reads
// it, a camera that frames its box, a key and a fill light, a floor just
// below the box, and default materials (scene_graph_materials()); the
// rest as a scene file that sets nothing else. Throws as a graph file's
// loader does.
Scene graph_alone_scene(const std::filesystem::path& file);

// The scene as mesh takes it: the graph alone, without the floor (and its
// material) that graph_alone_scene() adds for images.
void drop_floor(Scene& scene);

}  // namespace ms
