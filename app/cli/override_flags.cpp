#include "cli/override_flags.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>

#include "core/error.h"
#include "scene/toml_read.h"

namespace ms {
namespace {

constexpr std::size_t kMaxFlagBytes = 4096;  // a value longer than this is no hand-typed override

// "lights[0]" -> {lights}, {[0]}; "0" -> {[0]}; "fov" -> {fov}.
void parse_segment(const std::string& seg, const std::string& flag, std::vector<KeyStep>& path) {
  static const std::regex re(R"(^([A-Za-z0-9_-]*)((?:\[\d{1,6}\])*)$)");
  std::smatch m;
  if (seg.empty() || !std::regex_match(seg, m, re) || (m[1].length() == 0 && m[2].length() == 0))
    fail_input("invalid key " + quote(seg), {}, 0, flag,
               "a key is dotted names, e.g. camera.fov, materials.ball.color or lights[0].intensity");
  const std::string name = m[1];
  if (!name.empty()) {
    const bool number = std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (number && name.size() > 6) fail_input("invalid index " + quote(name), {}, 0, flag);
    path.push_back(number ? KeyStep{{}, std::stoul(name), true} : KeyStep{name, 0, false});
  }
  const std::string indices = m[2];
  for (std::size_t at = 0; (at = indices.find('[', at)) != std::string::npos; ++at)
    path.push_back(KeyStep{{}, std::stoul(indices.substr(at + 1)), true});
}

// A TOML value, or a bare word (fast, other.glsl) as a string.
toml::array parse_value(const std::string& text, const std::string& flag) {
  if (text.empty()) fail_input("no value after '='", {}, 0, flag, "e.g. --set camera.fov=30");
  if (text.find_first_of("\r\n") != std::string::npos) fail_input("the value spans lines", {}, 0, flag);
  toml::array out;
  toml::table t;
  bool parsed = false;
  const std::string line = "v = " + text;
#if TOML_EXCEPTIONS  // as scene/load.cpp: the Debian library throws
  try {
    t = toml::parse(line, std::string_view{flag});
    parsed = true;
  } catch (const toml::parse_error&) {
  }
#else
  if (toml::parse_result r = toml::parse(line, std::string_view{flag})) {
    t = std::move(r).table();
    parsed = true;
  }
#endif
  if (parsed && t.size() == 1 && t.contains("v")) {
    t["v"].node()->visit([&](auto& v) { out.push_back(std::move(v)); });
    return out;
  }
  static const std::regex bare(R"(^[A-Za-z_./][^\s"'\[\]{}#=,]*$)");
  if (!std::regex_match(text, bare))
    fail_input("invalid value " + quote(text), {}, 0, flag,
               "a TOML value: 30, true, \"text\", [1, 0, 0]; a bare word is a string");
  out.push_back(text);
  return out;
}

}  // namespace

SceneOverride parse_set_flag(const std::string& text) {
  const std::size_t eq = text.find('=');
  const std::string key = text.substr(0, std::min(eq, text.size()));
  SceneOverride o;
  o.flag = "--set " + printable(key);
  if (text.size() > kMaxFlagBytes) fail_input("the override is longer than 4096 bytes", {}, 0, "--set");
  if (eq == std::string::npos || key.empty())
    fail_input("expected KEY=VALUE, got " + quote(text), {}, 0, "--set", "e.g. --set camera.fov=30");
  std::size_t start = 0;
  while (start <= key.size()) {
    const std::size_t dot = std::min(key.find('.', start), key.size());
    parse_segment(key.substr(start, dot - start), o.flag, o.path);
    start = dot + 1;
  }
  if (o.path.size() > 16) fail_input("the key has more than 16 parts", {}, 0, o.flag);
  o.value = parse_value(text.substr(eq + 1), o.flag);
  return o;
}

UniformValue parse_uniform_flag(const std::string& text) {
  static const std::regex ident(R"(^[A-Za-z_][A-Za-z0-9_]*$)");
  const std::size_t eq = text.find('=');
  UniformValue u;
  u.name = text.substr(0, std::min(eq, text.size()));
  if (text.size() > kMaxFlagBytes) fail_input("the value is longer than 4096 bytes", {}, 0, "--uniform");
  if (eq == std::string::npos || !std::regex_match(u.name, ident))
    fail_input("expected NAME=VALUE with NAME a GLSL identifier, got " + quote(text), {}, 0, "--uniform",
               "e.g. --uniform uTwist=1.25 or --uniform uTint=[1,0.8,0.6]");
  const std::string flag = "--uniform " + u.name;
  std::string value = text.substr(eq + 1);
  if (!value.empty() && value.front() != '[' && value.find(',') != std::string::npos) value = "[" + value + "]";
  const toml::array parsed = parse_value(value, flag);
  const toml::node& v = parsed[0];
  auto number = [&](const toml::node& n) {
    const std::optional<double> d = n.value<double>();  // an integer too
    if (!n.is_number() || !d)
      fail_input("invalid value " + quote(text.substr(eq + 1)), {}, 0, flag, "a number, or [x, y, z] for a vector");
    if (!std::isfinite(*d)) fail_input("the value must be finite, got " + format_number(*d), {}, 0, flag);
    u.values.push_back(*d);
  };
  if (const toml::array* a = v.as_array()) {
    if (a->empty() || a->size() > 4) fail_input("a vector has 2 to 4 numbers", {}, 0, flag);
    for (const toml::node& n : *a) number(n);
  } else {
    number(v);
  }
  return u;
}

void add_override_flags(CLI::App* cmd, Overrides& out) {
  // Parsed once CLI11 has every value (an exception thrown from a callback
  // while it is still reading the command line would end the process).
  cmd->add_option_function<std::vector<std::string>>(
         "--set",
         [&out](const std::vector<std::string>& v) {
           for (const std::string& s : v) {
             out.set.push_back(parse_set_flag(s));
             out.as_given.push_back("--set " + s);
           }
         },
         "Override a scene key before it is checked, e.g. camera.fov=30, materials.ball.color=[1,0,0], "
         "lights[0].intensity=3, quality.preset=fast; it beats an [[animation]] of the key (repeatable; "
         "docs/usage.md#overrides)")
      ->allow_extra_args(false);  // one value each: `--set a=1 scene.toml` leaves the scene alone
  cmd->add_option_function<std::vector<std::string>>(
         "--uniform",
         [&out](const std::vector<std::string>& v) {
           for (const std::string& s : v) {
             out.uniforms.push_back(parse_uniform_flag(s));
             out.as_given.push_back("--uniform " + s);
           }
         },
         "Set a ranged uniform of the scene's shader (a viewer slider), e.g. uTwist=1.25 or uTint=[1,0.8,0.6]; "
         "checked against its type and range (repeatable)")
      ->allow_extra_args(false);
}

}  // namespace ms
