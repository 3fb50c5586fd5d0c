// Shadertoy API JSON, written by the tests that feed the binary a shader of
// their own (the site's layout, docs/shadertoy.md):
//
//   write_file(dir / "s.json", shader({pass("Buffer A", "buffer", 257, code_a, buffer_input(0, 257)),
//                                      pass("Image", "image", 0, code, buffer_input(0, 257))}));
#pragma once
#include <string>
#include <vector>

namespace ms::test {

// GLSL as a JSON string's contents: quotes and newlines escaped.
inline std::string json_escape(const std::string& code) {
  std::string esc;
  for (char c : code) esc += c == '"' ? std::string("\\\"") : c == '\n' ? std::string("\\n") : std::string(1, c);
  return esc;
}

// A render pass; `inputs` is the JSON array's text, `out_id` the output's id
// as JSON (a number, or a quoted string as Cube A's), empty for none.
inline std::string pass(const std::string& name, const std::string& type, const std::string& out_id,
                        const std::string& code, const std::string& inputs = "") {
  return "{\"name\": \"" + name + "\", \"type\": \"" + type + "\", \"code\": \"" + json_escape(code) +
         "\", \"inputs\": [" + inputs + "], \"outputs\": [" +
         (out_id.empty() ? "" : "{\"id\": " + out_id + ", \"channel\": 0}") + "]}";
}
// The same with a numeric output id; 0 for none (the Image pass).
inline std::string pass(const std::string& name, const std::string& type, int output, const std::string& code,
                        const std::string& inputs = "") {
  return pass(name, type, output > 0 ? std::to_string(output) : std::string(), code, inputs);
}

// A buffer pass's output read on `channel`, with a sampler object's JSON if given.
inline std::string buffer_input(int channel, int id, const std::string& sampler = "") {
  return "{\"id\": " + std::to_string(id) + ", \"ctype\": \"buffer\", \"channel\": " + std::to_string(channel) +
         (sampler.empty() ? "" : ", \"sampler\": " + sampler) + "}";
}

// The whole file: {"Shader": {"info": ..., "renderpass": [passes]}}.
inline std::string shader(const std::vector<std::string>& passes, const std::string& name = "t") {
  std::string s = "{\"Shader\": {\"info\": {\"name\": \"" + name + "\"}, \"renderpass\": [";
  for (size_t i = 0; i < passes.size(); ++i) s += (i ? ", " : "") + passes[i];
  return s + "]}}";
}

}  // namespace ms::test
