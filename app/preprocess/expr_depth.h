// The syntax-tree depth the driver's compiler will build for the code it
// is fed, estimated token by token after macro expansion.
//
// Why: Mesa's GLSL compiler recurses once per tree level (about 0.7 KB of
// stack each, docs/reliability.md), and a left-associative chain such as
// `a + b + c + ...` is as deep as it is long, although the parser's own
// stack stays flat. So each expression is parsed with C's precedences
// (shunting-yard, no recursion) into depths alone: a leaf is 1, an
// operator, call, index or member access one more than its deepest
// operand, a parenthesis nothing, and a block one more than its deepest
// statement. Two operands in a row (`float x`, `return y`) start a new
// expression, which keeps declarations and keywords out of the way.
//
//   ExprDepth d;
//   for (const PpToken& t : tokens) d.add(t);   // d.deepest() so far
#pragma once
#include <vector>

#include "preprocess/pp_token.h"

namespace ms {

class ExprDepth {
 public:
  // Feeds one token; returns the deepest tree finished so far.
  int add(const PpToken& t);
  int deepest() const { return deepest_; }

 private:
  struct Op {
    int precedence = 0;
    bool unary = false;
  };
  struct Frame {
    char close = 0;            // the bracket that ends it; 0 for the file level
    bool applies = false;      // a call or index: applies to the operand before it
    std::vector<int> operands; // depths of the operands not yet combined
    std::vector<Op> ops;
    bool want_operand = true;
    int best = 0;              // the deepest finished expression in the frame
  };
  void operand(int depth);
  void binary(int precedence, bool right_assoc);
  void reduce_one();
  void finish_expression();
  void open(char close, bool applies);
  void close(char c);
  void note(int depth);

  std::vector<Frame> frames_;
  int deepest_ = 0;
};

}  // namespace ms
