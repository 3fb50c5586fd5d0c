#include "preprocess/preprocess.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <system_error>

#include "io/input_file.h"
#include "core/error.h"
#include "preprocess/directive.h"

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

namespace {

// Encoded line numbers must stay below 2^31.
constexpr int kMaxFiles = 21000;

class Preprocessor {
 public:
  explicit Preprocessor(const PreprocessOptions& opts) : opts_(opts), roots_(resolved_roots(opts.roots)) {
    if (opts.model_driver) engine_ = std::make_unique<MacroEngine>(opts.limits, out_.files);
  }

  ShaderSource run(std::string_view root_text, const std::string& root_name, const fs::path& root_dir) {
    out_.files.push_back(root_name);
    paths_.push_back({});
    process(root_text, 0, root_dir);
    if (engine_) engine_->finish();
    return std::move(out_);
  }

 private:
  void process(std::string_view text, int file, const fs::path& dir) {
    const bool is_root = file == 0;
    bool in_comment = false;
    bool expanded = false;  // an include was expanded: re-sync after group switches
    bool seen_code = false; // root only: #version must precede everything else
    stack_.push_back(file);
    if (engine_) engine_->begin_file();
    int physical = 0;
    long shift = 0;  // a user's #line: the line numbers it gives minus the physical ones
    for (std::string_view line : split_lines(text)) {
      const int line_no = static_cast<int>(++physical + shift);
      // The line after the last (an include's return) must still encode into this file.
      if (physical > kLineStride - 2)
        fail_input("file is too long for line mapping (limit " + std::to_string(kLineStride - 2) + " lines)",
                   out_.files[file]);
      const bool starts_in_comment = in_comment;
      in_comment = ends_in_comment(line, in_comment);
      Directive d = starts_in_comment ? Directive{} : parse_directive(line);
      const bool dead = engine_ && engine_->region() == MacroEngine::Region::dead;
      switch (d.kind) {
        case DirectiveKind::include:
          if (dead) {  // the driver drops it with its group: so do we, unread
            out_.text += "// #include skipped: its #if group is not compiled\n";
            break;
          }
          if (!d.problem.empty()) fail_input(d.problem, out_.files[file], line_no);
          include(d, file, line_no, dir);
          expanded = true;
          break;
        case DirectiveKind::pragma_once:
          if (!is_root && !dead) once_.insert(paths_[file]);
          out_.text += "// #pragma once (handled by marchstudio)\n";
          break;
        case DirectiveKind::version:
          if (!is_root)
            fail_input("#version is only allowed in the root shader", out_.files[file], line_no, {},
                       "library and scene files must not declare a #version");
          if (seen_code) fail_input("#version must come before anything else", out_.files[file], line_no);
          emit(line, {file, line_no});
          break;
        case DirectiveKind::line:
          // `#line L`: the next line is L of this same file, in our encoding.
          if (is_root || !d.problem.empty() || dead) {
            emit(line, {file, line_no});
            break;
          }
          if (d.line > kLineStride - 2)
            fail_input("#line " + std::to_string(d.line) + " is beyond marchstudio's line mapping (limit " +
                           std::to_string(kLineStride - 2) + ")",
                       out_.files[file], line_no);
          shift = d.line - (physical + 1);
          line_directive(static_cast<int>(d.line), file);
          break;
        case DirectiveKind::group_switch:
          emit(line, {file, line_no});
          if (expanded) line_directive(static_cast<int>(physical + 1 + shift), file);
          break;
        default:
          emit(line, {file, line_no});
          break;
      }
      if (!is_blank_or_comment(line, starts_in_comment)) seen_code = true;
    }
    if (in_comment) fail_input("unterminated /* comment", out_.files[file], static_cast<int>(physical + shift));
    if (engine_) engine_->end_file();
    stack_.pop_back();
  }

  // A line the driver reads as it is; the engine reads it too.
  void emit(std::string_view line, PpWhere where) {
    out_.text.append(line).push_back('\n');
    check_size(where);
    if (engine_) engine_->line(line, where);
  }

  void check_size(PpWhere where) const {
    if (out_.text.size() <= opts_.limits.max_text_bytes) return;
    // The file included most often is the likely cause (an include diamond).
    std::string hint = "the driver would need gigabytes to compile it";
    int most = 0;
    const fs::path* which = nullptr;
    for (const auto& [path, n] : included_)
      if (n > most) { most = n; which = &path; }
    if (which && most > 1)
      hint = "'" + display_path(*which) + "' is included " + std::to_string(most) +
             " times: guard it with #pragma once or #ifndef";
    fail_input("the shader is larger than " + std::to_string(opts_.limits.max_text_bytes >> 20) +
                   " MiB with its includes expanded",
               out_.files[where.file], where.line, {}, hint);
  }

  void line_directive(int line, int file) {
    const long long encoded = static_cast<long long>(file) * kLineStride + line;
    out_.text += "#line " + std::to_string(encoded) + " " + std::to_string(file) + "\n";
  }

  void include(const Directive& d, int parent, int line_no, const fs::path& dir) {
    if (const auto it = opts_.inline_files.find(d.target); it != opts_.inline_files.end()) {
      include_inline(d.target, it->second, parent, line_no);
      return;
    }
    std::vector<fs::path> searched;
    fs::path outside;
    // Resolved once per directory and name: a file included a thousand
    // times is looked up once.
    const std::string key = dir.string() + (d.angled ? "\n<" : "\n\"") + d.target;
    auto known = resolved_.find(key);
    fs::path found = known != resolved_.end() ? known->second : resolve(d, dir, searched, outside);
    if (known == resolved_.end() && outside.empty() && !found.empty()) resolved_.emplace(key, found);
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
    // Level 1 is the first file the root includes; the root is not counted.
    if (static_cast<int>(stack_.size()) > kMaxIncludeDepth)
      fail_input("#include nested more than " + std::to_string(kMaxIncludeDepth) + " levels deep", out_.files[parent],
                 line_no, {}, "an include chain this long is most likely generated by mistake");
    int file = file_index(found);
    if (std::find(stack_.begin(), stack_.end(), file) != stack_.end()) {
      std::string chain;
      auto first = std::find(stack_.begin(), stack_.end(), file);
      for (auto it = first; it != stack_.end(); ++it) chain += out_.files[*it] + " -> ";
      chain += out_.files[file];
      fail_input("include cycle: " + chain, out_.files[parent], line_no);
    }
    const std::string& text = read(found, parent, line_no);
    if (engine_ && !guards_[found].empty() && engine_->defined(guards_[found])) {
      out_.text += "// #include \"" + d.target + "\" skipped: include guard " + guards_[found] + "\n";
      return;
    }
    ++included_[found];
    line_directive(1, file);
    process(text, file, found.parent_path());
    line_directive(line_no + 1, parent);
    check_size({parent, line_no});
  }
  // An inline source: a file index of its own, expanded like a file (its
  // key is not a path, so it cannot collide with one).
  void include_inline(const std::string& key, const PreprocessOptions::InlineFile& f, int parent, int line_no) {
    const fs::path id = "marchstudio-inline:" + key;
    int file = 0;
    if (const auto it = index_.find(id); it != index_.end()) {
      file = it->second;
    } else {
      file = static_cast<int>(out_.files.size());
      if (file >= kMaxFiles) fail_input("more than " + std::to_string(kMaxFiles - 1) + " files included", out_.files[0]);
      out_.files.push_back(f.display);
      paths_.push_back(id);
      index_.emplace(id, file);
    }
    if (std::find(stack_.begin(), stack_.end(), file) != stack_.end())
      fail_input("include cycle through " + f.display, out_.files[parent], line_no);
    line_directive(1, file);
    process(f.text, file, f.dir);
    line_directive(line_no + 1, parent);
    check_size({parent, line_no});
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
      const fs::path c = resolved_path(p);
      if (inside_roots(c, roots_)) return true;
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
    std::string text;
    if (const std::string why = input_file_problem(canonical); !why.empty())
      fail_input("include '" + display_path(canonical) + "' " + why, out_.files[parent], line_no);
    text = read_input_file(canonical, "include file");
    out_.dependencies.push_back(canonical);
    if (engine_) guards_[canonical] = include_guard(text);
    return texts_.emplace(canonical, std::move(text)).first->second;
  }

  const PreprocessOptions& opts_;
  const std::vector<fs::path> roots_;    // opts_.roots, canonical
  ShaderSource out_;
  std::unique_ptr<MacroEngine> engine_;  // after out_: it refers to out_.files
  std::vector<fs::path> paths_;          // file index -> canonical path (root: empty)
  std::map<fs::path, int> index_;        // canonical path -> file index
  std::map<fs::path, std::string> texts_;  // each file is read once
  std::map<fs::path, std::string> guards_; // its include guard macro, or empty
  std::map<fs::path, int> included_;     // how many times each file was expanded
  std::map<std::string, fs::path> resolved_;  // directory + include name -> the file found
  std::set<fs::path> once_;              // files that said #pragma once and were included
  std::vector<int> stack_;               // files being expanded, outermost first
};

}  // namespace

ShaderSource preprocess(std::string_view root_text, const std::string& root_name, const fs::path& root_dir,
                        const PreprocessOptions& opts) {
  return Preprocessor(opts).run(root_text, root_name, root_dir);
}

}  // namespace ms
