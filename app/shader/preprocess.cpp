#include "shader/preprocess.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <iterator>
#include <system_error>

#include "core/error.h"

// Line mapping. GLSL >= 3.30 (and what we generate is #version 450) defines
// `#line L S` as: the line AFTER the directive is line L of source string S.
// Checked with glslangValidator 12 (-S frag) and Mesa 22.3 llvmpipe (EGL
// surfaceless): "#line 1 1\nA\nB\nfoo bar;" is reported at "1:3" by both
// (glslang "ERROR: 1:3:", Mesa "1:3(1): error:"). GLSL <= 1.50 meant L+1
// (glslang reports 0:11 for "#version 150\n#line 10\nfoo bar;"), so this is
// exact only for #version 330 and later; the roots we build are 450.
// But Mesa keeps the source-string number only for lexer/parser errors: for
// errors found on the AST (undeclared identifiers, type errors) it reports
// string 0 with the right line ("#line 1 2\nfloat q = undefined_Q;" gives
// "0:1(11): error"), because its YYLLOC_DEFAULT sets source = 0. So line L of
// file N is emitted as line N*kLineStride+L (see preprocess.h); glslang and
// Mesa both accept line numbers up to 2^31-1.
//
// Each `#include` line is replaced by `#line` for line 1 of the file, then the
// file, then a `#line` back to the parent's next line, so counts stay exact
// without padding. A compiler skips #line directives inside an inactive #if
// group but still counts the skipped lines, so after every #else/#elif/#endif
// in a file that has expanded an include we re-sync with another `#line`
// (checked with glslang: without it, lines after "#if 0 / #include / #endif"
// are off by the size of the skipped file).

namespace ms {

namespace fs = std::filesystem;

std::string display_path(const fs::path& p) {
  if (p.empty()) return {};
  std::error_code ec;
  fs::path abs = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) abs = p;
  fs::path cwd = fs::current_path(ec);
  if (!ec) {
    fs::path ccwd = fs::weakly_canonical(cwd, ec);
    if (!ec) cwd = ccwd;
    fs::path rel = abs.lexically_relative(cwd);
    if (!rel.empty() && *rel.begin() != ".." && rel != ".") return rel.generic_string();
  }
  return abs.generic_string();
}

namespace {

// Absolute, symlinks resolved as far as the path exists, ".." folded.
fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  if (ec) a = p;
  fs::path c = fs::weakly_canonical(a, ec);
  return ec ? a.lexically_normal() : c;
}

bool inside(const fs::path& canonical, const std::vector<fs::path>& canonical_roots) {
  for (const fs::path& root : canonical_roots) {
    const fs::path rel = canonical.lexically_relative(root);
    if (!rel.empty() && *rel.begin() != "..") return true;
  }
  return false;
}

std::vector<fs::path> resolved_all(const std::vector<fs::path>& roots) {
  std::vector<fs::path> out;
  for (const fs::path& r : roots)
    if (!r.empty()) out.push_back(resolved(r));
  return out;
}

}  // namespace

bool within_roots(const fs::path& p, const std::vector<fs::path>& roots) {
  return inside(resolved(p), resolved_all(roots));
}

std::string describe_roots(const std::vector<fs::path>& roots) {
  std::vector<std::string> names;
  for (const fs::path& r : resolved_all(roots)) {
    std::string n = display_path(r);
    if (n.empty()) n.push_back('.');
    if (n.back() != '/') n.push_back('/');
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out.append(i + 1 == names.size() ? " and " : ", ");
    out.append(names[i]);
  }
  return out;
}

namespace {

// Encoded line numbers must stay below 2^31.
constexpr int kMaxFiles = 21000;
// Includes expand recursively: a chain of 10000 files overflowed the stack.
// GCC's cpp stops at 200 levels too.
constexpr size_t kMaxDepth = 200;

enum class Kind { none, include, pragma_once, version, group_switch, other };

struct Directive {
  Kind kind = Kind::none;
  std::string target;    // include: the name between the delimiters
  bool angled = false;   // include: <...> rather than "..."
  std::string problem;   // include: why the line is malformed, empty when fine
};

std::string_view trim(std::string_view s) {
  size_t b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Classifies a line that does not start inside a block comment.
Directive parse_directive(std::string_view line) {
  Directive d;
  std::string_view s = trim(line);
  if (s.empty() || s[0] != '#') return d;
  s = trim(s.substr(1));
  size_t n = 0;
  while (n < s.size() && is_word_char(s[n])) ++n;
  std::string_view word = s.substr(0, n);
  std::string_view rest = trim(s.substr(n));
  d.kind = Kind::other;
  if (word == "version") {
    d.kind = Kind::version;
  } else if (word == "else" || word == "elif" || word == "endif") {
    d.kind = Kind::group_switch;
  } else if (word == "pragma") {
    if (rest.substr(0, 4) == "once" && (rest.size() == 4 || !is_word_char(rest[4]))) d.kind = Kind::pragma_once;
  } else if (word == "include") {
    d.kind = Kind::include;
    if (rest.empty() || (rest[0] != '"' && rest[0] != '<')) {
      d.problem = "expected #include \"file\" or #include <file>";
      return d;
    }
    d.angled = rest[0] == '<';
    size_t close = rest.find(d.angled ? '>' : '"', 1);
    if (close == std::string_view::npos) {
      d.problem = "unterminated file name in #include";
      return d;
    }
    d.target = std::string(rest.substr(1, close - 1));
    std::string_view tail = trim(rest.substr(close + 1));
    if (d.target.empty()) d.problem = "empty file name in #include";
    else if (!tail.empty() && tail.substr(0, 2) != "//")
      d.problem = "unexpected text after #include: '" + std::string(tail) + "'";
  }
  return d;
}

// Updates the block-comment state over one line (GLSL has no string
// literals, so "/*" can only start a comment).
bool ends_in_comment(std::string_view line, bool in_comment) {
  for (size_t i = 0; i < line.size(); ++i) {
    if (in_comment) {
      if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') { in_comment = false; ++i; }
    } else if (line[i] == '/' && i + 1 < line.size()) {
      if (line[i + 1] == '/') return false;
      if (line[i + 1] == '*') { in_comment = true; ++i; }
    }
  }
  return in_comment;
}

bool is_blank_or_comment(std::string_view line, bool starts_in_comment) {
  bool c = starts_in_comment;
  for (size_t i = 0; i < line.size(); ++i) {
    if (c) {
      if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') { c = false; ++i; }
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/') {
      return true;
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '*') {
      c = true; ++i;
    } else if (line[i] != ' ' && line[i] != '\t') {
      return false;
    }
  }
  return true;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    size_t end = nl == std::string_view::npos ? text.size() : nl;
    std::string_view l = text.substr(pos, end - pos);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.push_back(l);
    pos = end + 1;
  }
  return lines;
}

class Preprocessor {
 public:
  explicit Preprocessor(const PreprocessOptions& opts) : opts_(opts), roots_(resolved_all(opts.roots)) {}

  ShaderSource run(std::string_view root_text, const std::string& root_name, const fs::path& root_dir) {
    out_.files.push_back(root_name);
    paths_.push_back({});
    process(root_text, 0, root_dir);
    return std::move(out_);
  }

 private:
  void process(std::string_view text, int file, const fs::path& dir) {
    const bool is_root = file == 0;
    bool in_comment = false;
    bool expanded = false;  // an include was expanded: re-sync after group switches
    bool seen_code = false; // root only: #version must precede everything else
    stack_.push_back(file);
    int line_no = 0;
    for (std::string_view line : split_lines(text)) {
      // The line after the last (an include's return) must still encode into this file.
      if (++line_no > kLineStride - 2)
        fail_input("file is too long for line mapping (limit " + std::to_string(kLineStride - 2) + " lines)",
                   out_.files[file]);
      const bool starts_in_comment = in_comment;
      in_comment = ends_in_comment(line, in_comment);
      Directive d = starts_in_comment ? Directive{} : parse_directive(line);
      switch (d.kind) {
        case Kind::include:
          if (!d.problem.empty()) fail_input(d.problem, out_.files[file], line_no);
          include(d, file, line_no, dir);
          expanded = true;
          break;
        case Kind::pragma_once:
          if (!is_root) once_.insert(paths_[file]);
          out_.text += "// #pragma once (handled by marchstudio)\n";
          break;
        case Kind::version:
          if (!is_root)
            fail_input("#version is only allowed in the root shader", out_.files[file], line_no, {},
                       "library and scene files must not declare a #version");
          if (seen_code) fail_input("#version must come before anything else", out_.files[file], line_no);
          out_.text.append(line).push_back('\n');
          break;
        case Kind::group_switch:
          out_.text.append(line).push_back('\n');
          if (expanded) line_directive(line_no + 1, file);
          break;
        default:
          out_.text.append(line).push_back('\n');
          break;
      }
      if (!is_blank_or_comment(line, starts_in_comment)) seen_code = true;
    }
    if (in_comment) fail_input("unterminated /* comment", out_.files[file], line_no);
    stack_.pop_back();
  }

  void line_directive(int line, int file) {
    const long long encoded = static_cast<long long>(file) * kLineStride + line;
    out_.text += "#line " + std::to_string(encoded) + " " + std::to_string(file) + "\n";
  }

  void include(const Directive& d, int parent, int line_no, const fs::path& dir) {
    std::vector<fs::path> searched;
    fs::path outside;
    fs::path found = resolve(d, dir, searched, outside);
    if (!outside.empty())
      fail_input("include '" + d.target + "' resolves to " + display_path(outside) +
                     ", outside the directories includes may read",
                 out_.files[parent], line_no, {},
                 "allowed: " + describe_roots(opts_.roots) + "; widen with --allow-include DIR");
    if (found.empty()) {
      std::string hint;
      if (fs::path(d.target).is_absolute()) {
        hint = "no such file";
      } else {
        hint = "searched ";
        for (size_t i = 0; i < searched.size(); ++i) hint += (i ? ", " : "") + display_path(searched[i]);
        if (searched.empty()) hint = "no include directories to search";
      }
      fail_input("cannot find include '" + d.target + "'", out_.files[parent], line_no, {}, hint);
    }
    if (once_.count(found)) {
      out_.text += "// #include \"" + d.target + "\" skipped: #pragma once\n";
      return;
    }
    if (stack_.size() >= kMaxDepth)
      fail_input("#include nested more than " + std::to_string(kMaxDepth) + " levels deep", out_.files[parent], line_no,
                 {}, "an include chain this long is most likely generated by mistake");
    int file = file_index(found);
    if (std::find(stack_.begin(), stack_.end(), file) != stack_.end()) {
      std::string chain;
      auto first = std::find(stack_.begin(), stack_.end(), file);
      for (auto it = first; it != stack_.end(); ++it) chain += out_.files[*it] + " -> ";
      chain += out_.files[file];
      fail_input("include cycle: " + chain, out_.files[parent], line_no);
    }
    line_directive(1, file);
    process(read(found, parent, line_no), file, found.parent_path());
    line_directive(line_no + 1, parent);
  }

  // The first candidate that is a regular file, canonical. With roots, a
  // candidate outside them stops the search (in `outside`) whether or not
  // it exists, so errors do not tell which files exist out there either.
  fs::path resolve(const Directive& d, const fs::path& dir, std::vector<fs::path>& searched, fs::path& outside) const {
    std::error_code ec;
    fs::path target(d.target);
    auto usable = [&](const fs::path& p) { return fs::is_regular_file(p, ec); };
    auto confined = [&](const fs::path& p) {
      if (roots_.empty()) return true;
      const fs::path c = resolved(p);
      if (inside(c, roots_)) return true;
      outside = c;
      return false;
    };
    // The canonical result is checked again: it is what gets opened.
    auto found = [&](const fs::path& p) {
      fs::path c = fs::canonical(p, ec);
      return !ec && confined(c) ? c : fs::path{};
    };
    if (target.is_absolute()) return confined(target) && usable(target) ? found(target) : fs::path{};
    auto add = [&](const fs::path& base) {
      if (std::find(searched.begin(), searched.end(), base) == searched.end()) searched.push_back(base);
    };
    if (!d.angled) add(dir);
    for (const auto& inc : opts_.include_dirs) add(inc);
    for (const auto& base : searched) {
      fs::path p = base / target;
      if (!confined(p)) return {};
      if (usable(p)) return found(p);
    }
    return {};
  }

  int file_index(const fs::path& canonical) {
    auto it = index_.find(canonical);
    if (it != index_.end()) return it->second;
    int idx = static_cast<int>(out_.files.size());
    if (idx >= kMaxFiles) fail_input("more than " + std::to_string(kMaxFiles - 1) + " files included", out_.files[0]);
    out_.files.push_back(display_path(canonical));
    paths_.push_back(canonical);
    index_.emplace(canonical, idx);
    return idx;
  }

  const std::string& read(const fs::path& canonical, int parent, int line_no) {
    auto it = texts_.find(canonical);
    if (it != texts_.end()) return it->second;
    std::ifstream in(canonical, std::ios::binary);
    std::string text;
    if (in) text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.is_open() || in.bad())
      fail_input("cannot read include '" + display_path(canonical) + "'", out_.files[parent], line_no);
    out_.dependencies.push_back(canonical);
    return texts_.emplace(canonical, std::move(text)).first->second;
  }

  const PreprocessOptions& opts_;
  const std::vector<fs::path> roots_;    // opts_.roots, canonical
  ShaderSource out_;
  std::vector<fs::path> paths_;          // file index -> canonical path (root: empty)
  std::map<fs::path, int> index_;        // canonical path -> file index
  std::map<fs::path, std::string> texts_;  // each file is read once
  std::set<fs::path> once_;              // files that said #pragma once and were included
  std::vector<int> stack_;               // files being expanded, outermost first
};

}  // namespace

ShaderSource preprocess(std::string_view root_text, const std::string& root_name, const fs::path& root_dir,
                        const PreprocessOptions& opts) {
  return Preprocessor(opts).run(root_text, root_name, root_dir);
}

}  // namespace ms
