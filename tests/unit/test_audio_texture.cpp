// Audio: Shadertoy's 512x2 music texture from a Web Audio
// AnalyserNode (fftSize 2048, smoothing 0.8, -100..-30 dB). A sine at the
// centre of FFT bin 100 that starts at 1 s: bins 99..101 saturate at 255 and
// every bin further away stays 0 (a Blackman window has three cosine terms,
// so a bin-centred sine leaks into two neighbours each side, no further);
// before it starts, the row is all zero. Row 1 is floor(128 (1 + s)) of the
// oldest 512 samples of the window. A WAV we write decodes to its samples,
// stereo mixed as 0.5 (L + R); a broken file is one error naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "core/error.h"
#include "io/audio.h"
#include "render/audio_texture.h"

namespace ms {
namespace {

constexpr int kRate = 44100;
constexpr double kBin100 = 100.0 * kRate / 2048.0;  // 2153.3203125 Hz

AudioClip sine_from_one_second(double seconds) {
  AudioClip c;
  c.sample_rate = kRate;
  c.mono.assign(static_cast<size_t>(seconds * kRate), 0.0f);
  for (size_t i = kRate; i < c.mono.size(); ++i)
    c.mono[i] = static_cast<float>(0.5 * std::sin(2.0 * M_PI * kBin100 * static_cast<double>(i - kRate) / kRate));
  return c;
}

TEST(AudioTexture, SinePeaksInItsBinOnlyAfterItStarts) {
  const AudioClip clip = sine_from_one_second(5.0);
  const AudioTexels before = audio_texels(clip, 0.99, 1.0 / 60);
  for (int k = 0; k < kAudioTexWidth; ++k) ASSERT_EQ(before[k], 0) << "bin " << k;
  const AudioTexels after = audio_texels(clip, 3.0, 1.0 / 60);
  for (int k = 0; k < kAudioTexWidth; ++k) {
    if (k >= 99 && k <= 101) EXPECT_EQ(after[k], 255) << "bin " << k;
    else if (std::abs(k - 100) > 2) EXPECT_EQ(after[k], 0) << "bin " << k;
  }
  // Bin 102 holds a2/2 of the amplitude: 20 log10(0.5 * 0.04 / 2) = -40 dB.
  EXPECT_EQ(after[102], static_cast<int>(std::floor(255.0 / 70.0 * (20.0 * std::log10(0.01) + 100.0))));
}

TEST(AudioTexture, WaveformRowIsTheOldestQuarterOfTheWindow) {
  const AudioClip clip = sine_from_one_second(5.0);
  const AudioTexels t = audio_texels(clip, 3.0, 1.0 / 60);
  const long long first = 3 * kRate - 2048;
  for (int k = 0; k < kAudioTexWidth; ++k)
    EXPECT_EQ(t[kAudioTexWidth + k], static_cast<int>(std::floor(128.0 * (1.0 + clip.mono[first + k])))) << k;
  // Silence reads 128, as Shadertoy's waveform at rest.
  const AudioTexels quiet = audio_texels(clip, 0.5, 1.0 / 60);
  for (int k = 0; k < kAudioTexWidth; ++k) ASSERT_EQ(quiet[kAudioTexWidth + k], 128);
}

TEST(AudioTexture, LoopsAndIsSilentBeforeTheStart) {
  const AudioClip clip = sine_from_one_second(2.0);
  EXPECT_EQ(audio_sample_at(clip, -1), 0.0f);
  EXPECT_EQ(audio_sample_at(clip, 2 * kRate + kRate + 7), clip.mono[kRate + 7]);
  // A time past the end plays the clip again: the same texels one length later.
  EXPECT_EQ(audio_texels(clip, 1.5, 0.0), audio_texels(clip, 3.5, 0.0));
}

TEST(AudioTexture, DownmixFollowsWebAudioSpeakers) {
  const float st[2] = {1.0f, 0.5f};
  EXPECT_FLOAT_EQ(downmix_to_mono(st, 2), 0.75f);
  const float quad[4] = {1, 1, 1, 1};
  EXPECT_FLOAT_EQ(downmix_to_mono(quad, 4), 1.0f);
  const float five1[6] = {1, 1, 1, 9, 1, 1};  // LFE (index 3) dropped
  EXPECT_FLOAT_EQ(downmix_to_mono(five1, 6), std::sqrt(0.5f) * 2 + 1 + 1);
}

// A 32-bit float WAV, written byte by byte (little endian).
void write_float_wav(const std::string& path, int channels, const std::vector<float>& interleaved) {
  std::ofstream f(path, std::ios::binary);
  auto u32 = [&](std::uint32_t v) { f.write(reinterpret_cast<const char*>(&v), 4); };
  auto u16 = [&](std::uint16_t v) { f.write(reinterpret_cast<const char*>(&v), 2); };
  const std::uint32_t bytes = static_cast<std::uint32_t>(interleaved.size() * 4);
  f.write("RIFF", 4); u32(36 + bytes); f.write("WAVEfmt ", 8); u32(16); u16(3); u16(static_cast<std::uint16_t>(channels));
  u32(kRate); u32(kRate * 4 * channels); u16(static_cast<std::uint16_t>(4 * channels)); u16(32);
  f.write("data", 4); u32(bytes);
  f.write(reinterpret_cast<const char*>(interleaved.data()), bytes);
}

TEST(AudioFile, StereoWavDecodesToTheMonoMix) {
  const std::string path = ::testing::TempDir() + "/ms_stereo.wav";
  write_float_wav(path, 2, {0.5f, -0.25f, 1.0f, 0.0f, -1.0f, -0.5f});
  const AudioClip c = read_audio(path);
  EXPECT_EQ(c.sample_rate, kRate);
  ASSERT_EQ(c.mono.size(), 3u);
  EXPECT_FLOAT_EQ(c.mono[0], 0.125f);
  EXPECT_FLOAT_EQ(c.mono[1], 0.5f);
  EXPECT_FLOAT_EQ(c.mono[2], -0.75f);
}

TEST(AudioFile, CorruptFileIsABadInputNamingIt) {
  const std::string path = ::testing::TempDir() + "/ms_corrupt.wav";
  std::ofstream(path) << "RIFF this is not audio";
  try {
    read_audio(path);
    FAIL() << "decoded a corrupt file";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().code, Exit::bad_input);
    EXPECT_NE(e.info().file.find("ms_corrupt.wav"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ms
