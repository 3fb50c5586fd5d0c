// io/compare.h's metrics and heat map with OpenImageIO's ImageBufAlgo
// (compare, absdiff, minchan, computePixelStats, color_map): no loops of
// our own over pixels. LDR-FLIP is io/flip.cpp's, in the executable.
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "io/oiio/oiio.h"

namespace ms::oiio {
namespace IBA = OIIO::ImageBufAlgo;

namespace {

// 8-bit levels k/255 read as float differ by 1/255 only up to float
// rounding; without this slack a one-level difference would count as over a
// 1/255 pixel threshold on some levels and not on others.
constexpr float kLevelSlack = 1e-6f;

// Channels compared: all but a trailing alpha. Renders are RGB(A) with alpha
// always 1, so this is "PSNR over RGB"; AOV EXRs (Z, N.x, ...) compare whole.
int compared_channels(const OIIO::ImageSpec& s) {
  const int n = s.nchannels;
  const bool trailing_alpha = n > 1 && (s.alpha_channel == n - 1 || s.channel_name(n - 1) == "A");
  return trailing_alpha ? n - 1 : n;
}

std::string size_text(const OIIO::ImageSpec& s) {
  return std::to_string(s.width) + "x" + std::to_string(s.height);
}

void check_comparable(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  const OIIO::ImageSpec &sa = a.spec(), &sb = b.spec();
  if (sa.width != sb.width || sa.height != sb.height || sa.depth != sb.depth)
    fail_input("images differ in size: " + size_text(sa) + " vs " + size_text(sb));
  if (sa.nchannels != sb.nchannels)
    fail_input("images differ in channel count: " + std::to_string(sa.nchannels) + " vs " +
               std::to_string(sb.nchannels));
}

// The whole data window of `ref`, channels [0, n). B's window is laid on
// A's: files we compare have no offsets, and sizes are already equal.
OIIO::ROI compare_roi(const OIIO::ImageBuf& ref, int n) {
  OIIO::ROI roi = OIIO::get_roi(ref.spec());
  roi.chbegin = 0;
  roi.chend = n;
  return roi;
}

std::int64_t count_nonfinite(const OIIO::ImageBuf& img, OIIO::ROI roi) {
  const OIIO::ImageBufAlgo::PixelStats st = IBA::computePixelStats(img, roi);
  std::int64_t n = 0;
  for (size_t c = 0; c < st.nancount.size(); ++c) n += st.nancount[c] + st.infcount[c];
  return n;
}

Image to_image(const OIIO::ImageBuf& buf, std::vector<std::string> channels) {
  const OIIO::ImageSpec& s = buf.spec();
  Image img;
  img.width = s.width;
  img.height = s.height;
  img.channels = std::move(channels);
  img.pixels.resize(static_cast<size_t>(s.width) * s.height * s.nchannels);
  if (!buf.get_pixels(OIIO::get_roi(s), OIIO::TypeDesc::FLOAT, img.pixels.data()))
    fail_system("cannot read back the diff image: " + buf.geterror());
  return img;
}

// An ImageBuf that views (does not copy) an ms::Image's pixels; `img` must outlive it.
OIIO::ImageBuf view_image(const Image& img) {
  OIIO::ImageSpec spec(img.width, img.height, img.nchannels(), OIIO::TypeDesc::FLOAT);
  spec.channelnames = img.channels;
  spec.alpha_channel = -1;
  for (int c = 0; c < img.nchannels(); ++c)
    if (img.channels[c] == "A") spec.alpha_channel = c;
  // ImageBuf wraps a mutable buffer; every use here only reads it.
  return OIIO::ImageBuf(spec, const_cast<float*>(img.pixels.data()));
}

CompareMetrics compare_bufs(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const CompareOptions& opts) {
  if (!(opts.pixel_threshold >= 0.0f) || !std::isfinite(opts.pixel_threshold))
    fail_input("pixel threshold must be a finite number >= 0", {}, 0, "--pixel-threshold");
  check_comparable(a, b);
  CompareMetrics m;
  m.width = a.spec().width;
  m.height = a.spec().height;
  m.channels = compared_channels(a.spec());
  m.pixel_threshold = opts.pixel_threshold;
  m.pixels = static_cast<std::int64_t>(m.width) * m.height;
  const OIIO::ROI roi = compare_roi(a, m.channels);

  // One pass gives mean, RMS, max and where, and (as "failures": pixels with
  // any channel strictly over failthresh) the count for the fraction metric.
  const float t = opts.pixel_threshold + kLevelSlack;
  const OIIO::ImageBufAlgo::CompareResults r = IBA::compare(a, b, t, t, roi);
  // r.error is also set merely because some pixel exceeded failthresh; only
  // an error with no such pixel is OpenImageIO failing to compare at all.
  if (r.error && r.nfail == 0) {
    const std::string why = OIIO::geterror();
    if (!why.empty()) fail_system("image comparison failed: " + why);
  }
  m.mean_abs = r.meanerror;
  m.max_abs = r.maxerror;
  m.max_x = r.maxx;
  m.max_y = r.maxy;
  m.max_channel = r.maxc;
  m.pixels_over = static_cast<std::int64_t>(r.nfail);
  m.fraction_over = m.pixels > 0 ? static_cast<double>(m.pixels_over) / static_cast<double>(m.pixels) : 0.0;
  // Peak 1.0. (OIIO's own PSNR is the same formula; spelt out for the +inf case.)
  m.psnr = r.rms_error > 0.0 ? 20.0 * std::log10(1.0 / r.rms_error) : std::numeric_limits<double>::infinity();
  m.nonfinite_a = count_nonfinite(a, roi);
  m.nonfinite_b = count_nonfinite(b, roi);
  if (m.nonfinite_a + m.nonfinite_b > 0) {  // compare()'s sums went NaN: say so plainly
    m.psnr = m.mean_abs = m.max_abs = std::numeric_limits<double>::quiet_NaN();
  }
  return m;
}

Image heatmap_bufs(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, float scale) {
  check_comparable(a, b);
  const OIIO::ROI roi = compare_roi(a, compared_channels(a.spec()));
  const OIIO::ImageBuf d = IBA::absdiff(a, b, roi);
  if (!(scale > 0.0f)) {  // the largest finite difference (the stats skip NaN/Inf)
    const OIIO::ImageBufAlgo::PixelStats st = IBA::computePixelStats(d);
    scale = 0.0f;
    for (float m : st.max) scale = std::max(scale, std::isfinite(m) ? m : 0.0f);
    if (scale == 0.0f) scale = 1.0f;  // all equal: the map stays black
  }
  // Non-finite differences go to the top of the scale, the worst kind. maxchan
  // would drop a NaN channel, so work in u = 1 - d/scale: NaN and -Inf there
  // become 0 (fixNonFinite), the per-pixel minimum of u is 1 - the largest
  // difference, and 1 - that is the map's input. (Written as -x + 1: OIIO
  // 2.4's sub(constant, image) computes image - constant.)
  auto one_minus = [](const OIIO::ImageBuf& x) { return IBA::add(IBA::mul(x, -1.0f), 1.0f); };
  OIIO::ImageBuf u = one_minus(IBA::mul(d, 1.0f / scale));
  IBA::fixNonFinite(u, u, OIIO::ImageBufAlgo::NONFINITE_BLACK);
  const OIIO::ImageBuf n = IBA::clamp(one_minus(IBA::minchan(u)), 0.0f, 1.0f);
  // OIIO's colour maps are linear values; encode to sRGB so a PNG shows the map as designed.
  const OIIO::ImageBuf heat = IBA::colorconvert(IBA::color_map(n, 0, "inferno"), "linear", "sRGB");
  if (heat.has_error()) fail_system("cannot build the diff heat map: " + heat.geterror());
  return to_image(heat, {"R", "G", "B"});
}

}  // namespace

CompareMetrics compare(const Image& a, const Image& b, const CompareOptions& opts) {
  return compare_bufs(view_image(a), view_image(b), opts);
}

Image diff_heatmap(const Image& a, const Image& b, float scale) {
  return heatmap_bufs(view_image(a), view_image(b), scale);
}

}  // namespace ms::oiio
