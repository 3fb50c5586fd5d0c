// Shadertoy's music texture, 512x2, one 8-bit channel (sampled (v, 0, 0, 1)):
// row 0 the first 512 bytes of getByteFrequencyData, row 1 the first 512 of
// getByteTimeDomainData, from a Web Audio AnalyserNode with the defaults
// Shadertoy leaves it (fftSize 2048, smoothingTimeConstant 0.8, minDecibels
// -100, maxDecibels -30). No GL here.
//
// The analysis of a frame at time t reads the 2048 samples that end just
// before sample floor(t x rate) (the clip loops, as Shadertoy's <audio
// loop> does; before time 0 is silence). Smoothing needs the analyser's
// previous analyses: to make a frame a function of its time alone, they are
// replayed, kHistory of them, one iTimeDelta apart, from zero. 0.8^64 < 1e-6,
// so this differs from an endless history far below one byte step.
#pragma once
#include <array>
#include <cstdint>

#include "io/audio.h"

namespace ms {

constexpr int kAudioTexWidth = 512;
constexpr int kAnalyserFft = 2048;
constexpr int kHistory = 64;

// Row 0 (FFT bytes) then row 1 (waveform bytes), 512 each: GL's row order.
using AudioTexels = std::array<std::uint8_t, 2 * kAudioTexWidth>;

// The sample at index i of the clip's playback (looped; 0 before the start).
float audio_sample_at(const AudioClip& clip, long long i);

// The texture at time `t` (seconds) with frames `dt` apart (iTimeDelta).
AudioTexels audio_texels(const AudioClip& clip, double t, double dt);

// Shadertoy's iSampleRate: a constant of its Image and Buffer passes, not
// the rate of any file.
constexpr float kShadertoySampleRate = 44100.0f;

}  // namespace ms
