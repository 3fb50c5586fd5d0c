// A model of the driver's GLSL preprocessor, run over the assembled shader
// before the driver sees it, so that what the driver would do without
// limit is bounded here, and what it does differently once its disk cache
// is warm is decided here:
//
// - macros are expanded the way C and glcpp expand them (hide sets, argument
//   pre-expansion, `##`), counting every token made: a "macro bomb"
//   (`#define A1 A0 A0` ... `A29`, 2^29 tokens) stops at the budget instead
//   of taking the machine's memory in the driver;
// - conditionals are evaluated, so `#error` in a live region fails the
//   shader every time (Mesa's cache skips the compile of a text it has seen
//   succeed), and the includer can skip includes the driver would drop;
// - the expanded code goes through ExprDepth, so an expression deeper than
//   the compile stack holds is refused with file:line instead of crashing.
//
// Conditions on the driver's GL_<extension> macros are unknown here: both
// branches are checked against the budgets, and #error in them is left to
// the driver.
//
//   MacroEngine e(limits, files);
//   e.line("#define N 3", {1, 1});   // each line, in the driver's order
//   e.finish();                                 // throws ms::Error
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "preprocess/expr_depth.h"
#include "preprocess/pp_token.h"

namespace ms {

struct PreprocessLimits {
  // The assembled shader, includes expanded, in bytes.
  std::size_t max_text_bytes = std::size_t{8} << 20;
  // Tokens that macro expansion may make, summed over the shader.
  std::size_t max_expanded_tokens = std::size_t{1} << 20;
  // ExprDepth's bound, within what core/big_stack.h's stack holds.
  int max_expression_depth = 50000;
};

class MacroEngine {
 public:
  enum class Region { live, dead, unknown };

  // `files`: display names by file index (ShaderSource::files), for errors;
  // it may grow while the engine runs.
  MacroEngine(const PreprocessLimits& limits, const std::vector<std::string>& files);
  ~MacroEngine();
  MacroEngine(const MacroEngine&) = delete;
  MacroEngine& operator=(const MacroEngine&) = delete;

  // One physical line, in the order the driver will read it, at `where`
  // (its file index and line, after any #line; __LINE__ and __FILE__ follow
  // from it through preprocess.h's line encoding).
  void line(std::string_view text, PpWhere where);
  // Comments and line continuations do not cross files.
  void begin_file();
  void end_file();
  // End of the shader: checks the rest and that every #if was closed.
  void finish();

  // Whether code here reaches the compiler (unknown: it depends on a
  // driver macro). An #include is expanded unless dead.
  Region region() const;
  bool defined(std::string_view name) const;

 private:
  struct Macro;
  struct Cond;
  void directive(const std::vector<PpToken>& toks, PpWhere where);
  void define(const std::vector<PpToken>& toks, size_t at, PpWhere where);
  void condition(std::string_view kind, const std::vector<PpToken>& toks, PpWhere where);
  bool evaluate(const std::vector<PpToken>& toks, size_t at, PpWhere where, bool& known);
  void flush();
  template <class Out>  // macro_expand.cpp alone instantiates it
  void expand(std::deque<PpToken>& in, Out&& out, int nesting);
  void expand_to(std::deque<PpToken>& in, std::vector<PpToken>& out, int nesting);
  std::vector<PpToken> substitute(const Macro& m, const std::vector<std::vector<PpToken>>& args,
                                  const PpToken& call, int hideset, int nesting);
  PpToken paste(const PpToken& a, const PpToken& b);
  void count(std::size_t made, PpWhere where);
  [[noreturn]] void fail(const std::string& what, PpWhere where, const std::string& hint = {}) const;
  std::string_view keep(std::string s);
  int hs_with(int hs, int macro);
  int hs_union(int a, int b);
  int hs_intersect(int a, int b);
  int intern(std::vector<int> set);
  void set_version(int version, std::string_view profile);

  const PreprocessLimits limits_;
  const std::vector<std::string>& files_;
  std::deque<Macro> macros_;                        // never moved: bodies point into them
  std::unordered_map<std::string, int> names_;      // defined name -> index in macros_
  std::vector<std::vector<int>> hidesets_;          // id -> sorted macro indices
  std::map<std::vector<int>, int> hideset_ids_;
  std::deque<std::string> arena_;                   // text of joined lines, pasted and made tokens
  std::vector<Cond> conds_;
  std::vector<PpToken> pending_;                    // live code not yet expanded
  std::vector<bool> comment_;                       // per open file: inside a block comment
  std::string continued_;                           // a line ending in '\' so far
  PpWhere continued_at_;
  bool continuing_ = false;
  std::size_t expanded_ = 0;
  ExprDepth depth_;
};

struct MacroEngine::Macro {
  std::string name;
  bool function = false;
  std::vector<std::string> params;
  std::string text;  // the body's spelling: body tokens point into it
  std::vector<PpToken> body;
};

}  // namespace ms
