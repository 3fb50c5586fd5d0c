// Shadertoy's JSON, as the API serves it and as the site exports it, into
// a ShaderProject (scene/project.h).
//
//   API:    {"Shader": {"info": {...}, "renderpass": [{"name", "type",
//            "code", "inputs": [{"id", "src", "ctype", "channel",
//            "sampler"}], "outputs": [{"id", "channel"}]}]}}
//           buffer outputs and inputs are ids 257..260 (A..D);
//   export: [{"info", "renderpass": [... "inputs": [{"id", "filepath",
//           "type", ...}]]}], buffer ids "4dXGR8", "XsXGR8", "4sXGR8", "XdfGR8".
//
// Errors name the file, the line of the offending value and its key path
// (renderpass[1].inputs[0].ctype); malformed JSON names line and column.
#pragma once
#include <string>
#include <string_view>

#include "scene/project.h"

namespace ms {

// `display` names the file in errors and in each pass's `where`.
ShaderProject load_shadertoy_json(std::string_view text, const std::string& display);

}  // namespace ms
