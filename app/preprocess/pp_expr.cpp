#include "preprocess/pp_expr.h"

#include <charconv>
#include <limits>

namespace ms {
namespace {

// Precedence climbing over C's operators; iterative in the binary levels,
// recursive only through parentheses, unary operators and ?:, whose depth
// the caller's line length bounds (and kMaxNesting caps).
class Evaluator {
 public:
  Evaluator(const std::vector<PpToken>& t, const std::function<bool(std::string_view)>& unknown)
      : t_(t), unknown_(unknown) {}

  PpValue run() {
    PpValue out;
    if (t_.empty()) return fail("#if with no expression");
    const std::int64_t v = conditional();
    if (error_.empty() && pos_ < t_.size()) fail("unexpected '" + std::string(t_[pos_].text) + "' in #if");
    out.error = error_;
    out.known = known_;
    out.value = v;
    return out;
  }

 private:
  static constexpr int kMaxNesting = 256;

  PpValue fail(std::string why) {
    if (error_.empty()) error_ = std::move(why);
    pos_ = t_.size();
    PpValue v;
    v.error = error_;
    return v;
  }
  bool at(std::string_view p) const { return pos_ < t_.size() && t_[pos_].kind == PpKind::punct && t_[pos_].text == p; }

  std::int64_t conditional() {
    if (++nesting_ > kMaxNesting) {
      fail("#if expression nested too deeply");
      return 0;
    }
    std::int64_t c = binary(0);
    if (at("?")) {
      ++pos_;
      const std::int64_t a = conditional();
      if (!at(":")) {
        fail("expected ':' in #if");
        return 0;
      }
      ++pos_;
      const std::int64_t b = conditional();
      c = c ? a : b;
    }
    --nesting_;
    return c;
  }

  // Binary levels, loosest first.
  static int level_of(std::string_view op) {
    static constexpr std::string_view levels[][4] = {
        {"||"}, {"&&"}, {"|"}, {"^"}, {"&"}, {"==", "!="}, {"<", ">", "<=", ">="}, {"<<", ">>"}, {"+", "-"},
        {"*", "/", "%"}};
    for (int l = 0; l < 10; ++l)
      for (std::string_view s : levels[l])
        if (!s.empty() && s == op) return l;
    return -1;
  }

  std::int64_t binary(int min_level) {
    std::int64_t lhs = unary();
    for (;;) {
      if (pos_ >= t_.size() || t_[pos_].kind != PpKind::punct) return lhs;
      const std::string_view op = t_[pos_].text;
      const int level = level_of(op);
      if (level < min_level || level < 0) return lhs;
      ++pos_;
      const std::int64_t rhs = binary(level + 1);
      if (!error_.empty()) return 0;
      lhs = apply(op, lhs, rhs);
    }
  }

  std::int64_t apply(std::string_view op, std::int64_t a, std::int64_t b) {
    using U = std::uint64_t;
    if (op == "||") return a || b;
    if (op == "&&") return a && b;
    if (op == "|") return a | b;
    if (op == "^") return a ^ b;
    if (op == "&") return a & b;
    if (op == "==") return a == b;
    if (op == "!=") return a != b;
    if (op == "<") return a < b;
    if (op == ">") return a > b;
    if (op == "<=") return a <= b;
    if (op == ">=") return a >= b;
    if (op == "<<") return static_cast<std::int64_t>(static_cast<U>(a) << (static_cast<U>(b) & 63));
    if (op == ">>") return a >> (static_cast<U>(b) & 63);
    if (op == "+") return static_cast<std::int64_t>(static_cast<U>(a) + static_cast<U>(b));
    if (op == "-") return static_cast<std::int64_t>(static_cast<U>(a) - static_cast<U>(b));
    if (op == "*") return static_cast<std::int64_t>(static_cast<U>(a) * static_cast<U>(b));
    if (b == 0) {
      // Mesa: "division by 0 in preprocessor directive". Unknown operands
      // evaluate as 0 here, so only a known zero is an error.
      if (known_) fail("division by zero in #if");
      return 0;
    }
    if (a == std::numeric_limits<std::int64_t>::min() && b == -1) return op == "/" ? a : 0;
    return op == "/" ? a / b : a % b;
  }

  std::int64_t unary() {
    if (pos_ >= t_.size()) {
      fail("#if expression ends early");
      return 0;
    }
    const PpToken& t = t_[pos_];
    if (t.kind == PpKind::punct) {
      if (t.text == "(") {
        ++pos_;
        const std::int64_t v = conditional();
        if (!at(")")) {
          fail("missing ')' in #if");
          return 0;
        }
        ++pos_;
        return v;
      }
      if (t.text == "-" || t.text == "+" || t.text == "!" || t.text == "~") {
        if (++nesting_ > kMaxNesting) {
          fail("#if expression nested too deeply");
          return 0;
        }
        ++pos_;
        const std::int64_t v = unary();
        --nesting_;
        if (t.text == "-") return static_cast<std::int64_t>(0 - static_cast<std::uint64_t>(v));
        if (t.text == "!") return !v;
        if (t.text == "~") return ~v;
        return v;
      }
      fail("unexpected '" + std::string(t.text) + "' in #if");
      return 0;
    }
    ++pos_;
    if (t.kind == PpKind::identifier) {
      if (unknown_(t.text)) known_ = false;
      return 0;
    }
    if (t.kind == PpKind::number) return number(t.text);
    fail("unexpected '" + std::string(t.text) + "' in #if");
    return 0;
  }

  std::int64_t number(std::string_view s) {
    std::string_view digits = s;
    while (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U')) digits.remove_suffix(1);
    int base = 10;
    if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
      base = 16;
      digits.remove_prefix(2);
    } else if (digits.size() > 1 && digits[0] == '0') {
      base = 8;
      digits.remove_prefix(1);
    }
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, base);
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
      fail("'" + std::string(s) + "' is not an integer in #if");
      return 0;
    }
    return static_cast<std::int64_t>(v);
  }

  const std::vector<PpToken>& t_;
  const std::function<bool(std::string_view)>& unknown_;
  size_t pos_ = 0;
  int nesting_ = 0;
  bool known_ = true;
  std::string error_;
};

}  // namespace

PpValue eval_pp_expression(const std::vector<PpToken>& tokens, const std::function<bool(std::string_view)>& unknown) {
  return Evaluator(tokens, unknown).run();
}

}  // namespace ms
