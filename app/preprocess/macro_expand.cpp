// MacroEngine's macro expansion (preprocess/macro_engine.h): the pending live
// code expanded and checked for depth, substitution, `##` and hide sets.
#include <algorithm>
#include <string>

#include "preprocess/macro_engine.h"
#include "preprocess/preprocess.h"

// Expansion follows C's rules (C17 6.10.3, which GLSL 4.60 section 3.3
// adopts) in Prosser's formulation: every token carries the set of macros
// it came out of (its hide set) and never expands one of them again; a
// function-like call's result gets the intersection of the name's and the
// closing parenthesis's sets plus the macro. Arguments are expanded before
// substitution except next to `##`. The result is rescanned together with
// the tokens after it, iteratively (no recursion per expansion level).

namespace ms {
namespace {

constexpr int kMaxNesting = 256;  // macro calls within macro arguments

}  // namespace

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
      if (in.empty() || !is_punct(in.front(), "(")) {  // a function-like name without a call
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
        if (is_punct(a, "(")) ++level;
        if (is_punct(a, ")") && level-- == 0) {
          close = a;
          closed = true;
          break;
        }
        if (is_punct(a, ",") && level == 0) args.emplace_back();
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
    if (is_punct(b[i], "##") && i + 1 < b.size() && (!out.empty() || placemarker)) {
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
    } else if (i + 1 < b.size() && is_punct(b[i + 1], "##")) {
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

void MacroEngine::expand_to(std::deque<PpToken>& in, std::vector<PpToken>& out, int nesting) {
  expand(in, [&](const PpToken& t) { out.push_back(t); }, nesting);
}

}  // namespace ms
