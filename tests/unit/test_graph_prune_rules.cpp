// The pruning rules of the seam combinators (graph_vocab.cpp's `reach`
// expressions, docs/scene-graph.md "Pruning") are exact: wherever a rule
// drops b on a cell, op(a, b) is a, to the bit, at every (a, b) the
// children's intervals allow. The expressions are read from the operator
// table itself and evaluated here as the pruning pass does; the operators
// are sdf_shaders/combinators.glsl's, written again in float.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>
#include <string>

#include "scene/graph_vocab.h"

namespace ms {
namespace {

// The GLSL reach expressions use numbers, P0, P1, ALO, AHI, + - * /,
// parentheses and max(x, y): a small recursive-descent evaluator in float.
class Reach {
 public:
  Reach(std::string_view text, float p0, float p1, float alo, float ahi)
      : s_(text), p0_(p0), p1_(p1), alo_(alo), ahi_(ahi) {}
  float value() {
    const float v = sum();
    skip();
    if (i_ != s_.size()) throw std::runtime_error("unparsed: " + std::string(s_.substr(i_)));
    return v;
  }

 private:
  void skip() {
    while (i_ < s_.size() && s_[i_] == ' ') ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  float sum() {
    float v = product();
    for (;;) {
      if (eat('+')) v = v + product();
      else if (eat('-')) v = v - product();
      else return v;
    }
  }
  float product() {
    float v = unary();
    for (;;) {
      if (eat('*')) v = v * unary();
      else if (eat('/')) v = v / unary();
      else return v;
    }
  }
  float unary() {
    if (eat('-')) return -unary();
    if (eat('(')) {
      const float v = sum();
      if (!eat(')')) throw std::runtime_error("expected )");
      return v;
    }
    skip();
    std::size_t j = i_;
    while (j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '.')) ++j;
    const std::string_view w = s_.substr(i_, j - i_);
    i_ = j;
    if (w == "max" || w == "min") {
      if (!eat('(')) throw std::runtime_error("expected (");
      const float x = sum();
      if (!eat(',')) throw std::runtime_error("expected ,");
      const float y = sum();
      if (!eat(')')) throw std::runtime_error("expected )");
      return w == "max" ? std::max(x, y) : std::min(x, y);
    }
    if (w == "P0") return p0_;
    if (w == "P1") return p1_;
    if (w == "ALO") return alo_;
    if (w == "AHI") return ahi_;
    if (w.empty() || !std::isdigit(static_cast<unsigned char>(w[0]))) throw std::runtime_error("word: " + std::string(w));
    return std::stof(std::string(w));
  }
  std::string_view s_;
  std::size_t i_ = 0;
  float p0_, p1_, alo_, ahi_;
};

float glsl_clamp(float x, float lo, float hi) { return std::min(std::max(x, lo), hi); }
float box_q(float x, float y) {
  return std::hypot(std::max(x, 0.0f), std::max(y, 0.0f)) + std::min(std::max(x, y), 0.0f);
}

// combinators.glsl, operator by operator.
float columns(float a, float b, float r, float n) {
  const float h = 0.70710678f, qx = (a - b) * h, qy = (a + b) * h, s = r * 1.41421356f / n;
  const float k = glsl_clamp(std::floor((qx + r * h) / s), 0.0f, n - 1.0f);
  const float column = std::hypot(qx - ((k + 0.5f) * s - r * h), qy - r * h) - 0.5f * s;
  return std::min(std::min(a, b), std::min(qy - r * h, column));
}
float stairs(float a, float b, float r, float n) {
  const float s = r / n, k = glsl_clamp(std::floor((a - b + r) / (2.0f * s)), 0.0f, n - 1.0f);
  float d = std::min(a, b);
  for (float i = std::max(k - 1.0f, 0.0f); i <= std::min(k + 1.0f, n - 1.0f); i += 1.0f)
    d = std::min(d, box_q(a - (i + 0.5f) * s, b - (r - (i + 0.5f) * s)));
  return d;
}
float engrave(float a, float b, float r, float) { return std::max(a, (a + r - std::fabs(b)) * 0.70710678f); }
float groove(float a, float b, float ra, float rb) { return std::max(a, std::min(a + ra, rb - std::fabs(b))); }
float tongue(float a, float b, float ra, float rb) { return std::min(a, std::max(a - ra, std::fabs(b) - rb)); }

struct Case {
  const char* name;
  float (*op)(float, float, float, float);
  bool symmetric;  // union-like: a may go as well as b
};

const GraphOperator& op_named(const char* name) {
  const int i = find_operator(name);
  EXPECT_GE(i, 0) << name;
  return graph_operators()[static_cast<std::size_t>(i)];
}

// Which child the rule drops on a cell (graph_prune.cpp's msDrop and
// msCut): 1 b, 2 a, 0 neither.
int drop(const GraphOperator& op, float p0, float p1, float alo, float ahi, float blo, float bhi) {
  if (op.family == OpFamily::union_) {
    if (blo >= ahi + Reach(op.reach, p0, p1, alo, ahi).value()) return 1;
    if (alo >= bhi + Reach(op.reach, p0, p1, blo, bhi).value()) return 2;
    return 0;
  }
  const float nearest = std::max({blo, -bhi, 0.0f});  // the least |b| on the cell
  return nearest >= Reach(op.reach, p0, p1, alo, ahi).value() ? 1 : 0;
}

TEST(GraphPruneRules, ADroppedChildNeverChangesTheSeamCombinators) {
  const Case cases[] = {{"opUnionColumns", columns, true}, {"opUnionStairs", stairs, true},
                        {"opEngrave", engrave, false}, {"opGroove", groove, false}, {"opTongue", tongue, false}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> centre(-1.0f, 1.0f), half(0.0f, 0.3f), len(0.01f, 0.3f);
  for (const Case& c : cases) {
    const GraphOperator& op = op_named(c.name);
    ASSERT_FALSE(op.reach.empty()) << c.name;
    int drops = 0, cells = 20000;
    for (int t = 0; t < cells; ++t) {
      const bool count = op.params.size() > 1 && !op.params[1].length;  // columns' and stairs' n
      const float p0 = len(rng), p1 = count ? static_cast<float>(1 + rng() % 5) : len(rng);
      const float ac = centre(rng), ah = half(rng), bc = centre(rng), bh = half(rng);
      const float alo = ac - ah, ahi = ac + ah, blo = bc - bh, bhi = bc + bh;
      const int d = drop(op, p0, p1, alo, ahi, blo, bhi);
      if (d == 0) continue;
      ++drops;
      ASSERT_TRUE(d == 1 || c.symmetric) << c.name;
      // The corners, the edges' points nearest the seam (b = 0, a = b) and
      // a grid over the rectangle.
      for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) {
          float a = alo + (ahi - alo) * static_cast<float>(i) / 16.0f, b = blo + (bhi - blo) * static_cast<float>(j) / 16.0f;
          if (j == 8 && blo < 0.0f && bhi > 0.0f) b = 0.0f;
          const float kept = d == 1 ? a : b, v = c.op(a, b, p0, p1);
          ASSERT_EQ(v, kept) << c.name << " p " << p0 << ", " << p1 << " at a " << a << " in [" << alo << ", " << ahi
                             << "], b " << b << " in [" << blo << ", " << bhi << "], dropping " << (d == 1 ? "b" : "a");
          // A union takes the nearer child's material, so the kept one is never farther.
          if (c.symmetric) ASSERT_LE(kept, d == 1 ? b : a) << c.name;
        }
    }
    // The rule must also fire: about half the sampled cells are far enough.
    EXPECT_GT(drops, cells / 10) << c.name;
  }
}

// Where a cut's rule keeps b, some point of the cell needs it: the rule is
// the least |b| itself, not a margin above it.
TEST(GraphPruneRules, TheCutsKeepBOnlyWhereSomePointNeedsIt) {
  const Case cases[] = {{"opEngrave", engrave, false}, {"opGroove", groove, false}, {"opTongue", tongue, false}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> centre(-1.0f, 1.0f), half(0.0f, 0.3f), len(0.01f, 0.3f);
  for (const Case& c : cases) {
    const GraphOperator& op = op_named(c.name);
    for (int t = 0; t < 20000; ++t) {
      const float p0 = len(rng), p1 = len(rng), ac = centre(rng), ah = half(rng), bc = centre(rng), bh = half(rng);
      const float alo = ac - ah, ahi = ac + ah, blo = bc - bh, bhi = bc + bh;
      const float nearest = std::max({blo, -bhi, 0.0f}), need = Reach(op.reach, p0, p1, alo, ahi).value();
      if (nearest >= need - 1e-4f) continue;  // dropped, or too close to tell from rounding
      const float b = blo > 0.0f ? blo : (bhi < 0.0f ? bhi : 0.0f);
      const bool differs = c.op(alo, b, p0, p1) != alo || c.op(ahi, b, p0, p1) != ahi;
      EXPECT_TRUE(differs) << c.name << " keeps b on [" << alo << ", " << ahi << "] x [" << blo << ", " << bhi
                           << "] where a alone would do";
    }
  }
}

// The stairs look at three steps only; their field is still the least over
// every step, so the bounds above (which hold for each step) hold for it.
TEST(GraphPruneRules, TheStairsThreeStepsAreTheLeastOverEveryStep) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> v(-0.5f, 0.5f), len(0.01f, 0.3f);
  for (int t = 0; t < 100000; ++t) {
    const float a = v(rng), b = v(rng), r = len(rng), n = static_cast<float>(1 + rng() % 6), s = r / n;
    float all = std::min(a, b);
    for (float i = 0.0f; i <= n - 1.0f; i += 1.0f) all = std::min(all, box_q(a - (i + 0.5f) * s, b - (r - (i + 0.5f) * s)));
    ASSERT_EQ(stairs(a, b, r, n), all) << "a " << a << ", b " << b << ", r " << r << ", n " << n;
  }
}

// The pipe and the blend are never equal to one child: they alone keep both.
TEST(GraphPruneRules, OnlyThePipeAndTheBlendHaveNoRule) {
  for (const GraphOperator& op : graph_operators())
    EXPECT_EQ(op.reach.empty(), op.name == "opPipe" || op.name == "opBlend") << op.name;
}

}  // namespace
}  // namespace ms
