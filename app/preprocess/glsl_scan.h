// Quick looks at GLSL text without a parser: comments blanked, and where a
// function is defined. Linear scans, never std::regex (libstdc++'s regex
// recurses per character and overflowed the stack on long inputs).
#pragma once
#include <string>
#include <string_view>

namespace ms {

// Comments replaced by spaces, newlines kept, so offsets still give lines.
std::string strip_comments(std::string_view s);

// Offset of the first `<type> <name> (` (whole words, any whitespace) in
// comment-free code, npos when none.
size_t find_definition(std::string_view code, std::string_view name, std::string_view type = "void");

// The return type of the first definition or prototype of `name` whose
// type is one of GLSL's own (float, vec3, ...), "" when none.
std::string definition_type(std::string_view code, std::string_view name);

// A label (a scene or pass name) safe inside a generated `//` or `/* */`
// comment: control characters, newlines included, become spaces, a
// backslash '/', and "*/" is broken up. A newline would end the comment
// and make the rest of the label live code.
std::string comment_label(std::string_view label);

// Why `value` cannot be a one-line #define's text ("" when it can): a
// line break, or a trailing backslash, which joins the next line.
std::string define_value_problem(std::string_view value);

}  // namespace ms
