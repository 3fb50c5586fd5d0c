// The worst-case range and Lipschitz bound of sdf_shaders/noise.glsl's noises.
//
// Every noise there is a sum over lattice corners of a weight times a random
// quantity: a value v in [-1, 1] (value noise) or a ramp g.(p - c) with a
// random unit gradient g (gradient and simplex noise). At a point p and for
// a unit direction u the directional derivative is linear in those random
// quantities, so its largest value over *every* choice of them is
//   value noise:      sum_c |grad w_c(p) . u|
//   gradient/simplex: sum_c |A_c(p) u|,  A_c = (p - c) grad w_c^T + w_c I,
// and the largest |noise| is sum_c w_c |p - c| (1 for value noise). The
// maxima over the cell and over u hold for any hash. noise.glsl states them
// (ramp noises divided by their range) plus 1% for the grid. Rerun after
// changing a kernel:
//   c++ -O2 -std=c++20 tools/noise-bounds.cpp -o build/noise-bounds && build/noise-bounds
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace {

template <int D> using Vec = std::array<double, D>;
template <int D> struct Term { double w; Vec<D> gw; Vec<D> d; };

template <int D> double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

void hermite(double t, double& s, double& ds) { s = t * t * (3 - 2 * t); ds = 6 * t * (1 - t); }
void quintic(double t, double& s, double& ds) {
  s = t * t * t * (t * (t * 6 - 15) + 10);
  ds = 30 * t * t * (t - 1) * (t - 1);
}

// The 2^D corners of the cell around f in [0,1]^D, with product weights.
template <int D>
std::vector<Term<D>> lattice(const Vec<D>& f, void (*fade)(double, double&, double&)) {
  Vec<D> s, ds;
  for (int i = 0; i < D; ++i) fade(f[i], s[i], ds[i]);
  std::vector<Term<D>> out;
  for (int c = 0; c < (1 << D); ++c) {
    Term<D> t{1.0, {}, {}};
    for (int i = 0; i < D; ++i) {
      const bool hi = (c >> i) & 1;
      t.w *= hi ? s[i] : 1 - s[i];
      t.d[i] = f[i] - (hi ? 1 : 0);
    }
    for (int k = 0; k < D; ++k) {
      double g = 1;
      for (int i = 0; i < D; ++i) {
        const bool hi = (c >> i) & 1;
        g *= i == k ? (hi ? ds[i] : -ds[i]) : (hi ? s[i] : 1 - s[i]);
      }
      t.gw[k] = g;
    }
    out.push_back(t);
  }
  return out;
}

// The D+1 corners of the simplex containing p (the skew of noise.glsl).
template <int D> std::vector<Term<D>> simplex(const Vec<D>& p, double r2) {
  const double F = D == 2 ? (std::sqrt(3.0) - 1) / 2 : 1.0 / 3, G = D == 2 ? (3 - std::sqrt(3.0)) / 6 : 1.0 / 6;
  double s = 0;
  for (double v : p) s += v;
  s *= F;
  Vec<D> i, x0;
  double is = 0;
  for (int k = 0; k < D; ++k) { i[k] = std::floor(p[k] + s); is += i[k]; }
  for (int k = 0; k < D; ++k) x0[k] = p[k] - i[k] + is * G;
  std::array<int, D> order;
  for (int k = 0; k < D; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return x0[a] > x0[b]; });
  std::vector<Term<D>> out;
  Vec<D> corner{};
  for (int k = 0; k <= D; ++k) {
    if (k > 0) corner[order[k - 1]] = 1;
    Term<D> t;
    double d2 = 0;
    for (int j = 0; j < D; ++j) { t.d[j] = x0[j] - corner[j] + k * G; d2 += t.d[j] * t.d[j]; }
    const double a = std::max(r2 - d2, 0.0);
    t.w = a * a * a * a;
    for (int j = 0; j < D; ++j) t.gw[j] = -8 * a * a * a * t.d[j];
    out.push_back(t);
  }
  return out;
}

template <int D> std::vector<Vec<D>> directions(int n) {
  std::vector<Vec<D>> u;
  for (int i = 0; i < n; ++i) {
    if constexpr (D == 2) {
      const double a = M_PI * i / n;  // u and -u give the same sum
      u.push_back({std::cos(a), std::sin(a)});
    } else {
      const double z = (i + 0.5) / n, phi = M_PI * (1 + std::sqrt(5.0)) * (i + 0.5), r = std::sqrt(1 - z * z);
      u.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
  }
  return u;
}

// max over u of the worst directional derivative at one point.
template <int D> double worst_slope(const std::vector<Term<D>>& terms, const std::vector<Vec<D>>& U, bool ramp) {
  double best = 0;
  for (const Vec<D>& u : U) {
    double sum = 0;
    for (const Term<D>& t : terms) {
      const double gu = dot<D>(t.gw, u);
      if (!ramp) { sum += std::abs(gu); continue; }
      Vec<D> au;
      for (int k = 0; k < D; ++k) au[k] = t.d[k] * gu + t.w * u[k];
      sum += std::sqrt(dot<D>(au, au));
    }
    best = std::max(best, sum);
  }
  return best;
}

template <int D> double worst_value(const std::vector<Term<D>>& terms) {
  double s = 0;
  for (const Term<D>& t : terms) s += t.w * std::sqrt(dot<D>(t.d, t.d));
  return s;
}

// Maximise fn over a grid of [lo, hi]^D, then regrid around the best point.
template <int D> double maximise(const std::function<double(const Vec<D>&)>& fn, double lo, double hi, int n) {
  Vec<D> best_p{};
  double best = -1, span = (hi - lo) / 2;
  Vec<D> centre;
  centre.fill((lo + hi) / 2);
  for (int round = 0; round < 5; ++round) {
    const int cells = round == 0 ? n : 13;
    std::array<int, D> idx{};
    for (;;) {
      Vec<D> p;
      for (int k = 0; k < D; ++k) p[k] = std::clamp(centre[k] - span + 2 * span * idx[k] / (cells - 1), lo, hi);
      const double v = fn(p);
      if (v > best) { best = v; best_p = p; }
      int k = 0;
      while (k < D && ++idx[k] == cells) idx[k++] = 0;
      if (k == D) break;
    }
    centre = best_p;
    span = round == 0 ? 2 * span / (n - 1) : span * 0.3;
  }
  return best;
}

void report(const char* name, double range, double lip) {
  std::printf("%-18s range %.7f  L %.5f  normalised L %.5f  (+1%%: %.4f)\n", name, range, lip, lip / range,
              1.01 * lip / range);
}

}  // namespace

int main() {
  const auto U2 = directions<2>(720);
  const auto U3 = directions<3>(1200);
  // Value noise, Hermite fade: the bound is symmetric in f -> 1 - f, so [0, 0.5]^D.
  report("noiseValue 2D", 1, maximise<2>([&](const Vec<2>& f) { return worst_slope<2>(lattice<2>(f, hermite), U2, false); }, 0, 0.5, 101));
  report("noiseValue 3D", 1, maximise<3>([&](const Vec<3>& f) { return worst_slope<3>(lattice<3>(f, hermite), U3, false); }, 0, 0.5, 21));
  // Gradient noise, quintic fade, unit gradients.
  {
    const double r = maximise<2>([&](const Vec<2>& f) { return worst_value<2>(lattice<2>(f, quintic)); }, 0, 1, 101);
    report("noiseGradient 2D", r, maximise<2>([&](const Vec<2>& f) { return worst_slope<2>(lattice<2>(f, quintic), U2, true); }, 0, 0.5, 101));
  }
  {
    const double r = maximise<3>([&](const Vec<3>& f) { return worst_value<3>(lattice<3>(f, quintic)); }, 0, 1, 21);
    report("noiseGradient 3D", r, maximise<3>([&](const Vec<3>& f) { return worst_slope<3>(lattice<3>(f, quintic), U3, true); }, 0, 0.5, 21));
  }
  // Simplex noise, kernel (0.5 - |d|^2)^4: over one skewed cell (it repeats).
  {
    const double r = maximise<2>([&](const Vec<2>& p) { return worst_value<2>(simplex<2>(p, 0.5)); }, 0, 1, 201);
    report("noiseSimplex 2D", r, maximise<2>([&](const Vec<2>& p) { return worst_slope<2>(simplex<2>(p, 0.5), U2, true); }, 0, 1, 201));
  }
  {
    const double r = maximise<3>([&](const Vec<3>& p) { return worst_value<3>(simplex<3>(p, 0.5)); }, 0, 1, 41);
    report("noiseSimplex 3D", r, maximise<3>([&](const Vec<3>& p) { return worst_slope<3>(simplex<3>(p, 0.5), U3, true); }, 0, 1, 41));
  }
  return 0;
}
