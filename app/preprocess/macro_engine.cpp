#include "preprocess/macro_engine.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "preprocess/pp_expr.h"
#include "preprocess/preprocess.h"

// The directives, conditionals and #if expressions; the expansion itself
// is macro_expand.cpp.

namespace ms {

struct MacroEngine::Cond {
  Region region = Region::live;  // of the branch being read
  Region outer = Region::live;   // of the code around the #if
  bool taken = false;            // a branch so far was surely live
  bool unknown_before = false;   // a branch so far depended on a driver macro
  bool seen_else = false;
  PpWhere where;
};

namespace {

// Comments become one space; `in_comment` carries a block comment to the next line.
std::string strip_comments(std::string_view line, bool& in_comment) {
  std::string out;
  out.reserve(line.size());
  for (size_t i = 0; i < line.size(); ++i) {
    if (in_comment) {
      if (line[i] == '*' && i + 1 < line.size() && line[i + 1] == '/') {
        in_comment = false;
        ++i;
        out.push_back(' ');
      }
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/') {
      break;
    } else if (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '*') {
      in_comment = true;
      ++i;
    } else {
      out.push_back(line[i]);
    }
  }
  return out;
}

// Names only the driver knows: its extension macros. The profile macros
// follow from #version; the rest starting GL_ are extensions or undefined.
bool driver_macro(std::string_view name) {
  return name.substr(0, 3) == "GL_" && name != "GL_ES" && name != "GL_core_profile" &&
         name != "GL_compatibility_profile" && name != "GL_FRAGMENT_PRECISION_HIGH" && name != "GL_SPIRV";
}

}  // namespace

MacroEngine::MacroEngine(const PreprocessLimits& limits, const std::vector<std::string>& files)
    : limits_(limits), files_(files) {
  hidesets_.push_back({});
  hideset_ids_[{}] = 0;
  set_version(110, "");
}

MacroEngine::~MacroEngine() = default;

void MacroEngine::fail(const std::string& what, PpWhere where, const std::string& hint) const {
  const std::string file = where.file >= 0 && where.file < static_cast<int>(files_.size()) ? files_[where.file] : "";
  fail_input(what, file, where.line, {}, hint);
}

std::string_view MacroEngine::keep(std::string s) { return arena_.emplace_back(std::move(s)); }

void MacroEngine::begin_file() {
  comment_.push_back(false);
  continuing_ = false;
}

void MacroEngine::end_file() {
  if (continuing_) {  // a last line ending in '\': what it continued ends here
    continuing_ = false;
    line("", continued_at_);
  }
  if (!comment_.empty()) comment_.pop_back();
}

MacroEngine::Region MacroEngine::region() const { return conds_.empty() ? Region::live : conds_.back().region; }

bool MacroEngine::defined(std::string_view name) const { return names_.count(std::string(name)) > 0; }

void MacroEngine::set_version(int version, std::string_view profile) {
  const bool es = profile == "es";
  const bool compat = profile == "compatibility";
  auto builtin = [&](const std::string& name, const std::string& value, bool on) {
    names_.erase(name);
    if (!on) return;
    Macro& m = macros_.emplace_back();
    m.name = name;
    m.text = value;
    lex_pp_tokens(m.text, {}, m.body);
    names_[name] = static_cast<int>(macros_.size()) - 1;
  };
  builtin("__VERSION__", std::to_string(version), true);
  builtin("GL_ES", "1", es);
  builtin("GL_core_profile", "1", !es && !compat && version >= 150);
  builtin("GL_compatibility_profile", "1", compat);
  // Mesa 22.3 defines it for #version 450 core (checked), as ES does for fragment shaders.
  builtin("GL_FRAGMENT_PRECISION_HIGH", "1", es || version >= 130);
}

void MacroEngine::line(std::string_view raw, PpWhere where) {
  if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
  std::string joined;  // a line continued with '\' is one line, at its first line
  if (continuing_ || (!raw.empty() && raw.back() == '\\')) {
    if (!continuing_) continued_at_ = where;
    continued_.append(raw);
    if (!raw.empty() && raw.back() == '\\') {
      continued_.pop_back();
      continuing_ = true;
      return;
    }
    continuing_ = false;
    joined.swap(continued_);
    raw = joined;
    where = continued_at_;
  }
  if (comment_.empty()) comment_.push_back(false);
  bool in_comment = comment_.back();
  std::string code = strip_comments(raw, in_comment);
  comment_.back() = in_comment;
  const size_t first = code.find_first_not_of(" \t\f\v");
  if (first != std::string::npos && code[first] == '#') {
    flush();  // the code so far is expanded with the macros it saw
    std::vector<PpToken> toks;
    lex_pp_tokens(code, where, toks);
    directive(toks, where);
    return;
  }
  if (region() == Region::dead) return;
  lex_pp_tokens(keep(std::move(code)), where, pending_);
}

void MacroEngine::finish() {
  flush();
  if (!conds_.empty()) fail("unterminated #if", conds_.back().where, "every #if, #ifdef and #ifndef needs an #endif");
}

void MacroEngine::directive(const std::vector<PpToken>& toks, PpWhere where) {
  if (toks.size() < 2) return;  // `#` alone does nothing
  const std::string_view name = toks[1].text;
  if (name == "if" || name == "ifdef" || name == "ifndef" || name == "elif" || name == "else" || name == "endif") {
    condition(name, toks, where);
    return;
  }
  if (region() == Region::dead) return;
  if (name == "define") {
    define(toks, 2, where);
  } else if (name == "undef") {
    if (toks.size() > 2) names_.erase(std::string(toks[2].text));
  } else if (name == "error") {
    if (region() != Region::live) return;  // left to the driver, whose macros decide
    std::string msg;
    for (size_t i = 2; i < toks.size(); ++i) msg += (i > 2 && toks[i].space_before ? " " : "") + std::string(toks[i].text);
    fail("#error " + msg, where);
  } else if (name == "version" && toks.size() > 2 && toks[2].kind == PpKind::number) {
    set_version(std::atoi(std::string(toks[2].text).c_str()), toks.size() > 3 ? toks[3].text : "");
  }
}

void MacroEngine::define(const std::vector<PpToken>& toks, size_t at, PpWhere where) {
  if (at >= toks.size() || toks[at].kind != PpKind::identifier) return;  // the driver reports it
  Macro m;
  m.name = std::string(toks[at].text);
  size_t i = at + 1;
  if (i < toks.size() && is_punct(toks[i], "(") && !toks[i].space_before) {
    m.function = true;
    for (++i; i < toks.size() && !is_punct(toks[i], ")"); ++i)
      if (toks[i].kind == PpKind::identifier) m.params.emplace_back(toks[i].text);
    ++i;
  }
  // The body's own copy of its spelling, re-lexed so its tokens point into it.
  for (size_t k = i; k < toks.size(); ++k) {
    if (k > i && toks[k].space_before) m.text.push_back(' ');
    m.text.append(toks[k].text);
  }
  Macro& stored = macros_.emplace_back(std::move(m));
  lex_pp_tokens(stored.text, where, stored.body);
  names_[stored.name] = static_cast<int>(macros_.size()) - 1;
}

void MacroEngine::condition(std::string_view kind, const std::vector<PpToken>& toks, PpWhere where) {
  auto test = [&](bool& known) -> bool {
    known = true;
    if (kind == "ifdef" || kind == "ifndef") {
      if (toks.size() < 3) fail("#" + std::string(kind) + " needs a macro name", where);
      const std::string_view n = toks[2].text;
      if (!defined(n) && driver_macro(n)) known = false;
      return defined(n) == (kind == "ifdef");
    }
    return evaluate(toks, 2, where, known);
  };
  if (kind == "if" || kind == "ifdef" || kind == "ifndef") {
    Cond c;
    c.outer = region();
    c.where = where;
    if (c.outer == Region::dead) {
      c.region = Region::dead;
      c.taken = true;
    } else {
      bool known = true;
      const bool yes = test(known);
      c.region = !known ? Region::unknown : yes ? c.outer : Region::dead;
      c.taken = known && yes;
      c.unknown_before = !known;
    }
    conds_.push_back(c);
    return;
  }
  if (conds_.empty()) fail("#" + std::string(kind) + " without #if", where);
  Cond& c = conds_.back();
  if (kind == "endif") {
    conds_.pop_back();
    return;
  }
  if (c.seen_else) fail("#" + std::string(kind) + " after #else", where);
  if (c.outer == Region::dead || c.taken) {
    c.region = Region::dead;
    c.seen_else = kind == "else";
    return;
  }
  bool known = true;
  const bool yes = kind == "else" ? true : test(known);
  c.seen_else = kind == "else";
  if (!known) {
    c.region = Region::unknown;
    c.unknown_before = true;
  } else if (yes) {
    c.region = c.unknown_before ? Region::unknown : c.outer;
    c.taken = true;
  } else {
    c.region = Region::dead;
  }
}

bool MacroEngine::evaluate(const std::vector<PpToken>& toks, size_t at, PpWhere where, bool& known) {
  static const std::string_view kOne = "1", kZero = "0";
  // `defined X` and `defined ( X )` first, then macro expansion.
  std::deque<PpToken> in;
  for (size_t i = at; i < toks.size(); ++i) {
    if (toks[i].kind == PpKind::identifier && toks[i].text == "defined") {
      size_t n = i + 1;
      const bool paren = n < toks.size() && is_punct(toks[n], "(");
      if (paren) ++n;
      if (n >= toks.size() || toks[n].kind != PpKind::identifier) fail("'defined' needs a macro name", where);
      if (paren && (n + 1 >= toks.size() || !is_punct(toks[n + 1], ")"))) fail("missing ')' after defined", where);
      PpToken v = toks[i];
      v.kind = PpKind::number;
      v.text = defined(toks[n].text) ? kOne : kZero;
      if (!defined(toks[n].text) && driver_macro(toks[n].text)) known = false;
      in.push_back(v);
      i = paren ? n + 1 : n;
      continue;
    }
    in.push_back(toks[i]);
  }
  std::vector<PpToken> expanded;
  expand_to(in, expanded, 0);
  const PpValue v = eval_pp_expression(expanded, [](std::string_view n) { return driver_macro(n); });
  if (!v.error.empty()) fail(v.error, where);
  known = known && v.known;
  return v.value != 0;
}

}  // namespace ms
