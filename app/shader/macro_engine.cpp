#include "shader/macro_engine.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "shader/pp_expr.h"
#include "shader/preprocess.h"

// Expansion follows C's rules (C17 6.10.3, which GLSL 4.60 section 3.3
// adopts) in Prosser's formulation: every token carries the set of macros
// it came out of (its hide set) and never expands one of them again; a
// function-like call's result gets the intersection of the name's and the
// closing parenthesis's sets plus the macro. Arguments are expanded before
// substitution except next to `##`. The result is rescanned together with
// the tokens after it, iteratively (no recursion per expansion level).

namespace ms {

struct MacroEngine::Macro {
  std::string name;
  bool function = false;
  std::vector<std::string> params;
  std::string text;            // the body's spelling: body tokens point into it
  std::vector<PpToken> body;
};

struct MacroEngine::Cond {
  Region region = Region::live;  // of the branch being read
  Region outer = Region::live;   // of the code around the #if
  bool taken = false;            // a branch so far was surely live
  bool unknown_before = false;   // a branch so far depended on a driver macro
  bool seen_else = false;
  PpWhere where;
};

namespace {

constexpr int kMaxNesting = 256;  // macro calls within macro arguments

bool is(const PpToken& t, std::string_view s) { return t.kind == PpKind::punct && t.text == s; }

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
  if (i < toks.size() && is(toks[i], "(") && !toks[i].space_before) {
    m.function = true;
    for (++i; i < toks.size() && !is(toks[i], ")"); ++i)
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
      const bool paren = n < toks.size() && is(toks[n], "(");
      if (paren) ++n;
      if (n >= toks.size() || toks[n].kind != PpKind::identifier) fail("'defined' needs a macro name", where);
      if (paren && (n + 1 >= toks.size() || !is(toks[n + 1], ")"))) fail("missing ')' after defined", where);
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
  expand(in, [&](const PpToken& t) { expanded.push_back(t); }, 0);
  const PpValue v = eval_pp_expression(expanded, [](std::string_view n) { return driver_macro(n); });
  if (!v.error.empty()) fail(v.error, where);
  known = known && v.known;
  return v.value != 0;
}

void MacroEngine::flush() {
  if (pending_.empty()) return;
  std::deque<PpToken> in(pending_.begin(), pending_.end());
  pending_.clear();
  expand(in, [&](const PpToken& t) {
    if (depth_.add(t) > limits_.max_expression_depth)
      fail("expression nested more than " + std::to_string(limits_.max_expression_depth) + " levels deep",
           t.where, "the driver's compiler recurses once per level; split it into several statements");
  }, 0);
  arena_.clear();  // nothing pending points into it any more
}

void MacroEngine::count(std::size_t made, PpWhere where) {
  expanded_ += made;
  if (expanded_ > limits_.max_expanded_tokens)
    fail("macro expansion makes more than " + std::to_string(limits_.max_expanded_tokens) + " tokens", where,
         "a macro that uses another one twice doubles per level (a \"macro bomb\")");
}

template <class Out>
void MacroEngine::expand(std::deque<PpToken>& in, Out&& out, int nesting) {
  if (nesting > kMaxNesting && !in.empty())
    fail("macro calls nested more than " + std::to_string(kMaxNesting) + " deep in arguments", in.front().where);
  while (!in.empty()) {
    PpToken t = in.front();
    in.pop_front();
    if (t.kind != PpKind::identifier) {
      out(t);
      continue;
    }
    if (t.text == "__LINE__" || t.text == "__FILE__") {
      const long v = t.text == "__FILE__" ? t.where.file
                     : t.where.file == 0 ? t.where.line
                                         : static_cast<long>(t.where.file) * kLineStride + t.where.line;
      t.kind = PpKind::number;
      t.text = keep(std::to_string(v));
      out(t);
      continue;
    }
    const auto it = names_.find(std::string(t.text));
    if (it == names_.end() || std::binary_search(hidesets_[t.hideset].begin(), hidesets_[t.hideset].end(), it->second)) {
      out(t);
      continue;
    }
    const int id = it->second;
    const Macro& m = macros_[id];
    std::vector<PpToken> body;
    if (!m.function) {
      body = substitute(m, {}, t, hs_with(t.hideset, id), nesting);
    } else {
      if (in.empty() || !is(in.front(), "(")) {  // a function-like name without a call
        out(t);
        continue;
      }
      in.pop_front();
      std::vector<std::vector<PpToken>> args(1);
      int level = 0;
      PpToken close;
      bool closed = false;
      while (!in.empty()) {
        PpToken a = in.front();
        in.pop_front();
        if (is(a, "(")) ++level;
        if (is(a, ")") && level-- == 0) {
          close = a;
          closed = true;
          break;
        }
        if (is(a, ",") && level == 0) args.emplace_back();
        else args.back().push_back(a);
      }
      if (!closed) fail("macro " + m.name + " call has unbalanced parentheses", t.where);
      if (m.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
      if (args.size() != m.params.size())
        fail("macro " + m.name + " takes " + std::to_string(m.params.size()) + " arguments, given " +
                 std::to_string(args.size()),
             t.where);
      body = substitute(m, args, t, hs_with(hs_intersect(t.hideset, close.hideset), id), nesting);
    }
    count(body.size(), t.where);
    in.insert(in.begin(), body.begin(), body.end());
  }
}

std::vector<PpToken> MacroEngine::substitute(const Macro& m, const std::vector<std::vector<PpToken>>& args,
                                             const PpToken& call, int hideset, int nesting) {
  auto param = [&](const PpToken& t) -> int {
    if (t.kind != PpKind::identifier) return -1;
    for (size_t i = 0; i < m.params.size(); ++i)
      if (m.params[i] == t.text) return static_cast<int>(i);
    return -1;
  };
  std::vector<std::vector<PpToken>> expanded(args.size());
  std::vector<bool> done(args.size(), false);
  std::vector<PpToken> out;
  bool placemarker = false;  // the last thing added was an empty argument before ##
  const std::vector<PpToken>& b = m.body;
  for (size_t i = 0; i < b.size(); ++i) {
    if (is(b[i], "##") && i + 1 < b.size() && (!out.empty() || placemarker)) {
      const int p = param(b[++i]);
      const std::vector<PpToken> rhs = p >= 0 ? args[p] : std::vector<PpToken>{b[i]};
      if (!rhs.empty()) {
        if (placemarker || out.empty()) out.push_back(rhs[0]);
        else out.back() = paste(out.back(), rhs[0]);
        out.insert(out.end(), rhs.begin() + 1, rhs.end());
      }
      placemarker = placemarker && rhs.empty();
      continue;
    }
    placemarker = false;
    const int p = param(b[i]);
    if (p < 0) {
      out.push_back(b[i]);
    } else if (i + 1 < b.size() && is(b[i + 1], "##")) {
      out.insert(out.end(), args[p].begin(), args[p].end());
      placemarker = args[p].empty();
    } else {
      if (!done[p]) {
        std::deque<PpToken> in(args[p].begin(), args[p].end());
        expand(in, [&](const PpToken& t) { expanded[p].push_back(t); }, nesting + 1);
        count(expanded[p].size(), call.where);
        done[p] = true;
      }
      out.insert(out.end(), expanded[p].begin(), expanded[p].end());
    }
  }
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].hideset = hs_union(out[i].hideset, hideset);
    out[i].where = call.where;
    if (i == 0) out[i].space_before = call.space_before;
  }
  return out;
}

PpToken MacroEngine::paste(const PpToken& a, const PpToken& b) {
  std::vector<PpToken> toks;
  const std::string_view text = keep(std::string(a.text) + std::string(b.text));
  lex_pp_tokens(text, a.where, toks);
  PpToken t = toks.empty() ? a : toks.front();  // more than one token: C leaves it undefined
  t.hideset = a.hideset;
  t.space_before = a.space_before;
  return t;
}

int MacroEngine::intern(std::vector<int> set) {
  const auto it = hideset_ids_.find(set);
  if (it != hideset_ids_.end()) return it->second;
  hidesets_.push_back(set);
  return hideset_ids_[std::move(set)] = static_cast<int>(hidesets_.size()) - 1;
}

int MacroEngine::hs_with(int hs, int macro) {
  std::vector<int> s = hidesets_[hs];
  const auto at = std::lower_bound(s.begin(), s.end(), macro);
  if (at != s.end() && *at == macro) return hs;
  s.insert(at, macro);
  return intern(std::move(s));
}

int MacroEngine::hs_union(int a, int b) {
  if (a == b || b == 0) return a;
  if (a == 0) return b;
  std::vector<int> s;
  std::set_union(hidesets_[a].begin(), hidesets_[a].end(), hidesets_[b].begin(), hidesets_[b].end(),
                 std::back_inserter(s));
  return intern(std::move(s));
}

int MacroEngine::hs_intersect(int a, int b) {
  if (a == b) return a;
  std::vector<int> s;
  std::set_intersection(hidesets_[a].begin(), hidesets_[a].end(), hidesets_[b].begin(), hidesets_[b].end(),
                        std::back_inserter(s));
  return intern(std::move(s));
}

}  // namespace ms
