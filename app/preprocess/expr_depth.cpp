#include "preprocess/expr_depth.h"

#include <algorithm>
#include <string_view>

namespace ms {
namespace {

// C's binary precedences, tightest last; assignments and ?: bind right.
int precedence_of(std::string_view op, bool& right) {
  right = false;
  if (op == "=" || op == "+=" || op == "-=" || op == "*=" || op == "/=" || op == "%=" || op == "<<=" ||
      op == ">>=" || op == "&=" || op == "^=" || op == "|=") {
    right = true;
    return 1;
  }
  if (op == "?" || op == ":") {
    right = true;
    return 2;
  }
  if (op == "||") return 3;
  if (op == "^^") return 4;
  if (op == "&&") return 5;
  if (op == "|") return 6;
  if (op == "^") return 7;
  if (op == "&") return 8;
  if (op == "==" || op == "!=") return 9;
  if (op == "<" || op == ">" || op == "<=" || op == ">=") return 10;
  if (op == "<<" || op == ">>") return 11;
  if (op == "+" || op == "-") return 12;
  if (op == "*" || op == "/" || op == "%") return 13;
  return 0;
}

constexpr int kUnary = 14;

}  // namespace

void ExprDepth::note(int depth) { deepest_ = std::max(deepest_, depth); }

void ExprDepth::reduce_one() {
  Frame& f = frames_.back();
  const Op op = f.ops.back();
  f.ops.pop_back();
  const size_t need = op.unary ? 1 : 2;
  if (f.operands.size() < need) return;  // malformed: the compiler's error to report
  int d = f.operands.back();
  f.operands.pop_back();
  if (!op.unary) {
    d = std::max(d, f.operands.back());
    f.operands.pop_back();
  }
  f.operands.push_back(d + 1);
  note(d + 1);
}

void ExprDepth::finish_expression() {
  Frame& f = frames_.back();
  while (!f.ops.empty()) reduce_one();
  for (int d : f.operands) f.best = std::max(f.best, d);
  f.operands.clear();
  f.want_operand = true;
}

void ExprDepth::operand(int depth) {
  Frame& f = frames_.back();
  if (!f.want_operand) finish_expression();  // `float x`, `return y`: a new expression
  f.operands.push_back(depth);
  f.want_operand = false;
  note(depth);
}

void ExprDepth::binary(int precedence, bool right_assoc) {
  Frame& f = frames_.back();
  while (!f.ops.empty() &&
         (f.ops.back().precedence > precedence || (f.ops.back().precedence == precedence && !right_assoc)))
    reduce_one();
  f.ops.push_back({precedence, false});
  f.want_operand = true;
}

void ExprDepth::open(char close, bool applies) {
  Frame f;
  f.close = close;
  f.applies = applies;
  frames_.push_back(std::move(f));
}

void ExprDepth::close(char c) {
  // A stray closer is the compiler's error to report; it changes nothing here.
  if (frames_.size() < 2 || frames_.back().close != c) return;
  finish_expression();
  const Frame done = std::move(frames_.back());
  frames_.pop_back();
  Frame& f = frames_.back();
  if (done.applies) {  // f(x), a[i]: one node over the operand and the contents
    if (!f.operands.empty()) f.operands.back() = std::max(f.operands.back(), done.best) + 1;
    note(f.operands.empty() ? done.best : f.operands.back());
  } else if (c == '}') {  // a block or an initializer list: one level
    if (f.want_operand) {
      operand(done.best + 1);
    } else {
      finish_expression();
      f.best = std::max(f.best, done.best + 1);
      note(done.best + 1);
    }
    finish_expression();
  } else {  // (expression): no node of its own
    operand(done.best);
  }
}

int ExprDepth::add(const PpToken& t) {
  if (frames_.empty()) frames_.emplace_back();
  Frame& f = frames_.back();
  if (t.kind == PpKind::identifier || t.kind == PpKind::number) {
    // After '.', a member name: the access is one node over the operand.
    if (!f.ops.empty() && f.ops.back().precedence == kUnary + 1) {
      f.ops.pop_back();
      if (!f.operands.empty()) note(++f.operands.back());
      f.want_operand = false;
    } else {
      operand(1);
    }
    return deepest_;
  }
  if (t.kind != PpKind::punct) return deepest_;
  const std::string_view s = t.text;
  if (s == "(" || s == "[" || s == "{") {
    const bool applies = !f.want_operand && s != "{";
    if (s == "{" && !f.want_operand) finish_expression();  // `if (x) {`: the block is a statement
    open(s == "(" ? ')' : s == "[" ? ']' : '}', applies);
  } else if (s == ")" || s == "]" || s == "}") {
    close(s[0]);
  } else if (s == "," || s == ";") {
    finish_expression();
  } else if (s == ".") {
    f.ops.push_back({kUnary + 1, true});  // resolved by the member name that follows
  } else if (s == "++" || s == "--") {
    if (f.want_operand) f.ops.push_back({kUnary, true});
    else if (!f.operands.empty()) note(++f.operands.back());  // postfix
  } else if (f.want_operand && (s == "-" || s == "+" || s == "!" || s == "~")) {
    f.ops.push_back({kUnary, true});
  } else {
    bool right = false;
    const int p = precedence_of(s, right);
    if (p > 0) binary(p, right);
  }
  return deepest_;
}

}  // namespace ms
