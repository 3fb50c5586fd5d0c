#include "sweep/plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <memory>

#include "core/format.h"
#include "io/image_backend.h"

namespace ms {
namespace {

using Color = ImageCanvas::Color;
using AlignX = ImageCanvas::AlignX;
using AlignY = ImageCanvas::AlignY;

constexpr int kPanelW = 720, kPanelH = 520;
constexpr int kLeft = 96, kRight = 24, kTop = 56, kBottom = 64;
constexpr Color kBlack{0.1f, 0.1f, 0.1f}, kGrid{0.88f, 0.88f, 0.88f}, kDot{0.55f, 0.55f, 0.55f},
    kFront{0.1f, 0.35f, 0.85f}, kBaseline{0.85f, 0.15f, 0.1f}, kDefault{0.1f, 0.65f, 0.2f},
    kPreset{0.95f, 0.55f, 0.05f}, kReference{0.5f, 0.2f, 0.7f};

// The drawing primitives are the image module's (io/image_backend.h).
struct Canvas {
  std::unique_ptr<ImageCanvas> img;
  void line(int x1, int y1, int x2, int y2, const Color& c) { img->line(x1, y1, x2, y2, c); }
  void box(int x1, int y1, int x2, int y2, const Color& c, bool fill) { img->box(x1, y1, x2, y2, c, fill); }
  void text(int x, int y, const std::string& s, int size, const Color& c, AlignX ax = AlignX::left,
            AlignY ay = AlignY::baseline) {
    img->text(x, y, s, size, c, ax, ay);
  }
  // A filled square of half-size r, outlined in black when `outline`.
  void dot(int x, int y, int r, const Color& c, bool outline) {
    box(x - r, y - r, x + r, y + r, c, true);
    if (outline) box(x - r - 1, y - r - 1, x + r + 1, y + r + 1, kBlack, false);
  }
  void triangle_up(int x, int y, int r, const Color& c) {
    for (int dy = 0; dy <= 2 * r; ++dy) line(x - dy / 2, y - r + dy, x + dy / 2, y - r + dy, c);
  }
};

std::string num(double v) { return format_number(v); }

// 1, 2, 5 x 10^k inside [lo, hi].
std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> t;
  for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= static_cast<int>(std::ceil(std::log10(hi))); ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (v >= lo && v <= hi) t.push_back(v);
    }
  return t;
}

void panel(Canvas& cv, int ox, const SweepResult& r, bool same_spp, const std::string& heading) {
  auto psnr = [&](const SweepRow& row) { return same_spp ? row.same_spp.psnr : row.supersampled.psnr; };
  auto front = [&](const SweepRow& row) { return same_spp ? row.pareto_same_spp : row.pareto_supersampled; };
  double tmin = 1e30, tmax = 0, pmin = 1e30, pmax = -1e30;
  for (const SweepRow& row : r.rows) {
    const double t = std::max(row_time_ms(r, row), 1e-3), p = psnr(row);
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
    if (std::isfinite(p)) {
      pmin = std::min(pmin, p);
      pmax = std::max(pmax, p);
    }
  }
  if (pmin > pmax) pmin = 0, pmax = 50;
  const double lx0 = std::log10(tmin / 1.25), lx1 = std::log10(tmax * 1.25);
  const double y0 = std::floor(pmin / 5.0) * 5.0, y1 = std::ceil(pmax / 5.0) * 5.0 + 5.0;  // headroom for inf
  const int px0 = ox + kLeft, px1 = ox + kPanelW - kRight, py0 = kTop, py1 = kPanelH - kBottom;
  auto X = [&](double t) {
    return px0 + static_cast<int>((std::log10(std::max(t, 1e-3)) - lx0) / (lx1 - lx0) * (px1 - px0) + 0.5);
  };
  auto Y = [&](double p) {
    const double q = std::isfinite(p) ? p : y1;
    return py1 - static_cast<int>((std::clamp(q, y0, y1) - y0) / (y1 - y0) * (py1 - py0) + 0.5);
  };

  // Grid, axes, ticks.
  for (double t : log_ticks(tmin / 1.25, tmax * 1.25)) {
    cv.line(X(t), py0, X(t), py1, kGrid);
    cv.text(X(t), py1 + 18, num(t), 13, kBlack, AlignX::center);
  }
  const double step = (y1 - y0) > 40 ? 10.0 : 5.0;
  for (double p = y0; p <= y1 + 1e-9; p += step) {
    cv.line(px0, Y(p), px1, Y(p), kGrid);
    cv.text(px0 - 6, Y(p), num(p), 13, kBlack, AlignX::right, AlignY::center);
  }
  cv.box(px0, py0, px1, py1, kBlack, false);
  const char* clock = r.clock == SweepClock::cpu    ? "process CPU"
                      : r.clock == SweepClock::wall ? "wall"
                      : r.gpu_timer                 ? "GPU"
                                                    : "wall";
  cv.text((px0 + px1) / 2, py1 + 44, std::string(clock) + " time per frame, ms (best round's median, log scale)", 14,
          kBlack, AlignX::center);
  cv.text(ox + 10, (py0 + py1) / 2, "PSNR\n(dB)", 14, kBlack, AlignX::left, AlignY::center);
  cv.text(px0, py0 - 12, heading, 15, kBlack);

  // Every row, then the front as a line through its points, then the marked rows on top.
  for (const SweepRow& row : r.rows) cv.dot(X(row_time_ms(r, row)), Y(psnr(row)), 3, kDot, false);
  std::vector<const SweepRow*> f;
  for (const SweepRow& row : r.rows)
    if (front(row)) f.push_back(&row);
  std::sort(f.begin(), f.end(), [&](auto a, auto b) { return row_time_ms(r, *a) < row_time_ms(r, *b); });
  for (size_t i = 1; i < f.size(); ++i)
    cv.line(X(row_time_ms(r, *f[i - 1])), Y(psnr(*f[i - 1])), X(row_time_ms(r, *f[i])), Y(psnr(*f[i])), kFront);
  for (const SweepRow* row : f) cv.dot(X(row_time_ms(r, *row)), Y(psnr(*row)), 4, kFront, false);
  for (const SweepRow& row : r.rows) {
    const std::string& n = row.config.name;
    if (row.config.axis != "preset") continue;
    const Color& c = n == "textbook" ? kBaseline : n == "balanced" ? kDefault : n == "reference" ? kReference : kPreset;
    const int x = X(row_time_ms(r, row)), y = Y(psnr(row));
    if (!std::isfinite(psnr(row)))
      cv.triangle_up(x, y + 8, 8, c);
    else
      cv.dot(x, y, n == "balanced" ? 8 : 6, c, true);
    cv.text(x + 12, y + (n == "balanced" ? -10 : 14), n == "balanced" ? "balanced (default)" : n, 14, c);
  }
}

}  // namespace

SweepPlot plot_sweep(const SweepResult& r, const std::string& title) {
  Canvas cv;
  cv.img = image_backend().canvas(2 * kPanelW, kPanelH, {1.0f, 1.0f, 1.0f});
  cv.text(kLeft, 26, title, 18, kBlack);
  panel(cv, 0, r, true, "error vs converged reference, same spp (tracing error)");
  panel(cv, kPanelW, r, false, "error vs converged reference, supersampled (overall fidelity)");
  SweepPlot out;
  out.has_text = cv.img->has_text();
  out.image = cv.img->pixels();
  return out;
}

}  // namespace ms
