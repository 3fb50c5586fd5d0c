#include "render/samples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace ms {
namespace {

// PCG32 step: small, well-distributed, and identical on every platform
// (std:: distributions are not specified bit-exactly).
struct Pcg32 {
  uint64_t state = 0x853c49e6748fea9bULL;
  uint32_t next() {
    uint64_t old = state;
    state = old * 6364136223846793005ULL + 1442695040888963407ULL;
    uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
  }
  float unit() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }  // [0,1)
};

}  // namespace

std::vector<glm::vec2> stratified_samples(int spp) {
  if (spp <= 1) return {glm::vec2(0.5f)};
  const int k = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(spp))));
  std::vector<int> strata(k * k);
  std::iota(strata.begin(), strata.end(), 0);
  Pcg32 rng;
  if (spp < k * k) {  // choose which strata to use: Fisher-Yates with the fixed seed
    for (int i = k * k - 1; i > 0; --i) std::swap(strata[i], strata[rng.next() % (i + 1)]);
  }
  std::vector<glm::vec2> out;
  out.reserve(spp);
  for (int i = 0; i < spp; ++i) {
    const int s = strata[i];
    const float jx = rng.unit(), jy = rng.unit();
    out.emplace_back((static_cast<float>(s % k) + jx) / k, (static_cast<float>(s / k) + jy) / k);
  }
  return out;
}

std::vector<glm::vec2> open_samples(int begin, int end) {
  // g: the plastic number, x^3 = x + 1; a = (1/g, 1/g^2) (Roberts 2018).
  const double g = 1.32471795724474602596, a1 = 1.0 / g, a2 = 1.0 / (g * g);
  std::vector<glm::vec2> out;
  for (int n = std::max(begin, 0); n < end; ++n) {
    if (n == 0) {
      out.emplace_back(0.5f);
      continue;
    }
    const double x = 0.5 + a1 * n, y = 0.5 + a2 * n;
    out.emplace_back(static_cast<float>(x - std::floor(x)), static_cast<float>(y - std::floor(y)));
  }
  return out;
}

}  // namespace ms
