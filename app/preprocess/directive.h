// The line-level view of GLSL that preprocess/preprocess.cpp works in: which
// directive a line is, where block comments run, and a file's include
// guard. No macro expansion here (preprocess/macro_engine.h does that).
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace ms {

enum class DirectiveKind { none, include, pragma_once, version, line, group_switch, other };

struct Directive {
  DirectiveKind kind = DirectiveKind::none;
  std::string target;    // include: the name between the delimiters
  bool angled = false;   // include: <...> rather than "..."
  std::string problem;   // include, line: why the line is malformed, empty when fine
  long line = 0;         // line: the number it sets
};

// Classifies a line that does not start inside a block comment.
Directive parse_directive(std::string_view line);

// The block-comment state after `line` (GLSL has no string literals, so
// "/*" can only start a comment).
bool ends_in_comment(std::string_view line, bool in_comment);
bool is_blank_or_comment(std::string_view line, bool starts_in_comment);

// Lines without their '\n' (and a '\r' before it).
std::vector<std::string_view> split_lines(std::string_view text);
// Every '\n'-separated piece as its own string, the one after a final
// '\n' included (empty), '\r' kept: joined with '\n' they give `text` back.
std::vector<std::string> line_strings(std::string_view text);

// The macro of a classic include guard, or empty: the file's first code is
// `#ifndef G` (or `#if !defined(G)`) and the #endif that closes it is its
// last. While G is defined, including the file again adds nothing.
std::string include_guard(std::string_view text);

}  // namespace ms
