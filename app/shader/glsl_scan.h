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

}  // namespace ms
