#include "render/audio_texture.h"

#include <kiss_fftr.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace ms {

namespace {

constexpr double kTau = 0.8, kMinDb = -100.0, kMaxDb = -30.0;

// Blackman window of the Web Audio spec (alpha 0.16), N = fftSize.
const std::vector<float>& blackman() {
  static const std::vector<float> w = [] {
    std::vector<float> v(kAnalyserFft);
    const double a0 = 0.42, a1 = 0.5, a2 = 0.08, pi = 3.14159265358979323846;
    for (int n = 0; n < kAnalyserFft; ++n)
      v[n] = static_cast<float>(a0 - a1 * std::cos(2 * pi * n / kAnalyserFft) + a2 * std::cos(4 * pi * n / kAnalyserFft));
    return v;
  }();
  return w;
}

long long end_sample(const AudioClip& clip, double t) {
  return static_cast<long long>(std::floor(t * clip.sample_rate));
}

}  // namespace

float audio_sample_at(const AudioClip& clip, long long i) {
  if (i < 0 || clip.mono.empty()) return 0.0f;
  return clip.mono[static_cast<size_t>(i % static_cast<long long>(clip.mono.size()))];
}

AudioTexels audio_texels(const AudioClip& clip, double t, double dt) {
  struct Cfg {
    kiss_fftr_cfg cfg = kiss_fftr_alloc(kAnalyserFft, 0, nullptr, nullptr);
    ~Cfg() { kiss_fftr_free(cfg); }
  };
  static thread_local Cfg fft;
  const std::vector<float>& w = blackman();
  std::vector<float> x(kAnalyserFft);
  std::vector<kiss_fft_cpx> spec(kAnalyserFft / 2 + 1);
  std::vector<double> smooth(kAnalyserFft / 2, 0.0);
  for (int j = kHistory; j >= 0; --j) {  // oldest first: the smoothing's order
    const long long end = end_sample(clip, t - j * dt);
    bool silent = true;
    for (int n = 0; n < kAnalyserFft; ++n) {
      const float s = audio_sample_at(clip, end - kAnalyserFft + n);
      silent = silent && s == 0.0f;
      x[n] = s * w[n];
    }
    if (silent) {  // |X| = 0: only the decay
      for (double& v : smooth) v *= kTau;
      continue;
    }
    kiss_fftr(fft.cfg, x.data(), spec.data());
    for (int k = 0; k < kAnalyserFft / 2; ++k) {
      const double mag = std::hypot(static_cast<double>(spec[k].r), static_cast<double>(spec[k].i)) / kAnalyserFft;
      smooth[k] = kTau * smooth[k] + (1.0 - kTau) * mag;
    }
  }
  AudioTexels out{};
  for (int k = 0; k < kAudioTexWidth; ++k) {
    const double db = 20.0 * std::log10(smooth[k]);  // -inf for 0: clipped to 0 below
    const double b = std::floor(255.0 / (kMaxDb - kMinDb) * (db - kMinDb));
    out[k] = static_cast<std::uint8_t>(std::clamp(std::isnan(b) ? 0.0 : b, 0.0, 255.0));
  }
  // getByteTimeDomainData into a shorter array keeps its first elements:
  // the oldest 512 of the 2048-sample window.
  const long long end = end_sample(clip, t);
  for (int k = 0; k < kAudioTexWidth; ++k) {
    const double b = std::floor(128.0 * (1.0 + audio_sample_at(clip, end - kAnalyserFft + k)));
    out[kAudioTexWidth + k] = static_cast<std::uint8_t>(std::clamp(b, 0.0, 255.0));
  }
  return out;
}

}  // namespace ms
