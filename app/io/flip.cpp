#include "io/flip.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace ms {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Plane = std::vector<float>;  // one channel, width * height, top row first
using Mat3 = std::array<std::array<double, 3>, 3>;

// Linear sRGB (Rec. 709 primaries, D65) to CIE XYZ, the matrix the paper's
// authors use (exact ratios of integers; its inverse is computed below).
constexpr Mat3 kRgbToXyz = {{{10135552.0 / 24577794, 8788810.0 / 24577794, 4435075.0 / 24577794},
                             {2613072.0 / 12288897, 8788810.0 / 12288897, 887015.0 / 12288897},
                             {1425312.0 / 73733382, 8788810.0 / 73733382, 70074185.0 / 73733382}}};
// The D65 white point in XYZ (Y = 1): the normalisation of YCxCz and L*a*b*.
constexpr std::array<double, 3> kWhite = {0.950428545, 1.0, 1.088900371};

Mat3 inverse(const Mat3& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
      r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
    }
  return r;
}

std::array<double, 3> mul(const Mat3& m, const std::array<double, 3>& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

double srgb_to_linear(double v) { return v > 0.04045 ? std::pow((v + 0.055) / 1.055, 2.4) : v / 12.92; }

// YCxCz: the linearised CIELAB of the paper's colour pipeline.
std::array<double, 3> xyz_to_ycxcz(const std::array<double, 3>& xyz) {
  const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
  return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

std::array<double, 3> ycxcz_to_xyz(const std::array<double, 3>& c) {
  const double y = (c[0] + 16.0) / 116.0;
  return {(y + c[1] / 500.0) * kWhite[0], y * kWhite[1], (y - c[2] / 200.0) * kWhite[2]};
}

// CIELAB of linear RGB, then the Hunt adjustment (chroma scaled by 0.01 L*).
std::array<double, 3> hunt_lab(const std::array<double, 3>& rgb) {
  const std::array<double, 3> xyz = mul(kRgbToXyz, rgb);
  constexpr double d = 6.0 / 29.0;
  auto f = [&](double t) { return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0; };
  const double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
  const double L = 116.0 * fy - 16.0;
  return {L, 0.01 * L * 500.0 * (fx - fy), 0.01 * L * 200.0 * (fy - fz)};
}

// HyAB: city-block in lightness, Euclidean in chroma.
double hyab(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// `in` convolved with kx along rows and ky along columns (both centred,
// odd length), edge pixels repeated past the border.
Plane convolve(const Plane& in, int w, int h, const std::vector<double>& kx, const std::vector<double>& ky) {
  Plane tmp(in.size()), out(in.size());
  const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int i = -rx; i <= rx; ++i) s += kx[i + rx] * in[static_cast<size_t>(y) * w + std::clamp(x + i, 0, w - 1)];
      tmp[static_cast<size_t>(y) * w + x] = static_cast<float>(s);
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int j = -ry; j <= ry; ++j) s += ky[j + ry] * tmp[static_cast<size_t>(std::clamp(y + j, 0, h - 1)) * w + x];
      out[static_cast<size_t>(y) * w + x] = static_cast<float>(s);
    }
  return out;
}

// A contrast sensitivity function as a spatial filter (the paper's
// a1 sqrt(pi/b1) exp(-pi^2 r^2/b1) + a2 ..., normalised to sum 1): a sum of
// two Gaussians, each separable, so two separable passes.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kAchromatic{1.0, 0.0047, 0.0, 1e-5}, kRedGreen{1.0, 0.0053, 0.0, 1e-5}, kBlueYellow{34.1, 0.04, 13.5, 0.025};

Plane csf_filter(const Plane& in, int w, int h, const Csf& c, double ppd) {
  // One radius for every channel, from the widest Gaussian of any of them.
  const double widest = std::max({kAchromatic.b1, kRedGreen.b1, kBlueYellow.b1, kBlueYellow.b2});
  const int r = static_cast<int>(std::ceil(3.0 * std::sqrt(widest / (2.0 * kPi * kPi)) * ppd));
  auto gaussian = [&](double b) {
    std::vector<double> g(2 * r + 1);
    for (int i = -r; i <= r; ++i) g[i + r] = std::exp(-kPi * kPi * (i / ppd) * (i / ppd) / b);
    return g;
  };
  auto sum = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s;
  };
  const std::vector<double> g1 = gaussian(c.b1);
  const double w1 = c.a1 * std::sqrt(kPi / c.b1);
  double total = w1 * sum(g1) * sum(g1);
  Plane out = convolve(in, w, h, g1, g1);
  for (float& v : out) v = static_cast<float>(v * w1);
  if (c.a2 != 0.0) {
    const std::vector<double> g2 = gaussian(c.b2);
    const double w2 = c.a2 * std::sqrt(kPi / c.b2);
    total += w2 * sum(g2) * sum(g2);
    const Plane second = convolve(in, w, h, g2, g2);
    for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(out[i] + w2 * second[i]);
  }
  for (float& v : out) v = static_cast<float>(v / total);
  return out;
}

// Edges (first derivative of a Gaussian) or points (second derivative) of
// the normalised achromatic channel: the magnitude of the x and y responses.
// The Gaussian's peak-to-trough is 0.082 degrees; positive and negative
// weights are each normalised to sum to +1 and -1.
Plane features(const Plane& y, int w, int h, double ppd, bool points) {
  const double sd = 0.5 * 0.082 * ppd;
  const int r = static_cast<int>(std::ceil(3.0 * sd));
  std::vector<double> g(2 * r + 1), d(2 * r + 1);
  double gsum = 0, pos = 0, neg = 0;
  for (int i = -r; i <= r; ++i) {
    const double e = std::exp(-(i * i) / (2.0 * sd * sd));
    g[i + r] = e;
    d[i + r] = points ? (i * i / (sd * sd) - 1.0) * e : -i * e;
    gsum += e;
    (d[i + r] > 0 ? pos : neg) += d[i + r];
  }
  for (double& v : g) v /= gsum;
  for (double& v : d) v = v > 0 ? v / pos : v / -neg;  // the sign depends on x alone: separable
  const Plane fx = convolve(y, w, h, d, g), fy = convolve(y, w, h, g, d);
  Plane out(y.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = std::hypot(fx[i], fy[i]);
  return out;
}

struct Opponent {
  Plane c[3];  // Y, Cx, Cz
};

Opponent to_ycxcz(const Image& img) {
  const size_t n = static_cast<size_t>(img.width) * img.height, nch = img.channels.size();
  Opponent o;
  for (Plane& p : o.c) p.resize(n);
  for (size_t i = 0; i < n; ++i) {
    std::array<double, 3> rgb;
    for (int k = 0; k < 3; ++k) rgb[k] = srgb_to_linear(std::clamp(static_cast<double>(img.pixels[i * nch + k]), 0.0, 1.0));
    const std::array<double, 3> c = xyz_to_ycxcz(mul(kRgbToXyz, rgb));
    for (int k = 0; k < 3; ++k) o.c[k][i] = static_cast<float>(c[k]);
  }
  return o;
}

}  // namespace

double flip_default_ppd() { return 0.7 * (3840.0 / 0.7) * kPi / 180.0; }

FlipMap flip_ldr(const Image& reference, const Image& test, double ppd) {
  if (reference.width != test.width || reference.height != test.height)
    fail_input("FLIP: images differ in size");
  if (reference.channels.size() < 3 || test.channels.size() < 3) fail_input("FLIP needs RGB images");
  const int w = reference.width, h = reference.height;
  const size_t n = static_cast<size_t>(w) * h;
  const Opponent ref = to_ycxcz(reference), tst = to_ycxcz(test);
  const Csf csf[3] = {kAchromatic, kRedGreen, kBlueYellow};
  Opponent fref, ftst;
  for (int k = 0; k < 3; ++k) {
    fref.c[k] = csf_filter(ref.c[k], w, h, csf[k], ppd);
    ftst.c[k] = csf_filter(tst.c[k], w, h, csf[k], ppd);
  }
  // Feature pipeline on the unfiltered achromatic channel, Y/Yn in [0, 1].
  Plane yr(n), yt(n);
  for (size_t i = 0; i < n; ++i) {
    yr[i] = (ref.c[0][i] + 16.0f) / 116.0f;
    yt[i] = (tst.c[0][i] + 16.0f) / 116.0f;
  }
  const Plane er = features(yr, w, h, ppd, false), et = features(yt, w, h, ppd, false);
  const Plane pr = features(yr, w, h, ppd, true), pt = features(yt, w, h, ppd, true);

  const Mat3 xyz_to_rgb = inverse(kRgbToXyz);
  auto filtered_rgb = [&](const Opponent& o, size_t i) {
    std::array<double, 3> rgb = mul(xyz_to_rgb, ycxcz_to_xyz({o.c[0][i], o.c[1][i], o.c[2][i]}));
    for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);  // back into the RGB cube
    return rgb;
  };
  constexpr double qc = 0.7, qf = 0.5, pc = 0.4, ptop = 0.95;
  const double cmax = std::pow(hyab(hunt_lab({0, 1, 0}), hunt_lab({0, 0, 1})), qc);  // green vs blue: the largest
  FlipMap out;
  out.width = w;
  out.height = h;
  out.error.resize(n);
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const double e = std::pow(hyab(hunt_lab(filtered_rgb(fref, i)), hunt_lab(filtered_rgb(ftst, i))), qc);
    // Errors below pc * cmax map to [0, pt], the rest to (pt, 1].
    const double dc = e < pc * cmax ? ptop / (pc * cmax) * e : ptop + (e - pc * cmax) / (cmax - pc * cmax) * (1.0 - ptop);
    const double df = std::pow(std::max(std::abs(er[i] - et[i]), std::abs(pr[i] - pt[i])) / std::sqrt(2.0), qf);
    const double v = std::pow(dc, 1.0 - df);
    out.error[i] = static_cast<float>(v);
    sum += v;
    out.max = std::max(out.max, v);
  }
  out.mean = n ? sum / static_cast<double>(n) : 0.0;
  return out;
}

}  // namespace ms
