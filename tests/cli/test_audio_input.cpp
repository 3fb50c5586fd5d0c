// Audio inputs through the real binary: a music input reads a WAV
// the test writes (a sine at the centre of FFT bin 100 from 1 s on) from the
// media directory, and the shader sees Shadertoy's 512x2 texture texel for
// texel as render/audio_texture.h computes it (its own test checks the
// analyser against the sine), iSampleRate 44100, iChannelResolution (512, 2);
// a corrupt file, a missing one and a microphone are one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "io/audio.h"
#include "io/image_io.h"
#include "render/audio_texture.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

void write_tone_wav(const fs::path& path) {
  const int rate = 44100;
  std::vector<std::int16_t> s(static_cast<size_t>(4 * rate), 0);
  for (size_t i = rate; i < s.size(); ++i)
    s[i] = static_cast<std::int16_t>(std::lround(16384.0 * std::sin(2.0 * M_PI * 100.0 * (i - rate) / 2048.0)));
  std::ofstream f(path, std::ios::binary);
  auto u32 = [&](std::uint32_t v) { f.write(reinterpret_cast<const char*>(&v), 4); };
  auto u16 = [&](std::uint16_t v) { f.write(reinterpret_cast<const char*>(&v), 2); };
  const std::uint32_t bytes = static_cast<std::uint32_t>(s.size() * 2);
  f.write("RIFF", 4); u32(36 + bytes); f.write("WAVEfmt ", 8); u32(16); u16(1); u16(1);
  u32(rate); u32(rate * 2); u16(2); u16(16);
  f.write("data", 4); u32(bytes);
  f.write(reinterpret_cast<const char*>(s.data()), bytes);
}

std::string music_json(const std::string& ctype, const std::string& src) {
  return "{\"Shader\": {\"info\": {\"name\": \"a\"}, \"renderpass\": [{\"name\": \"Image\", \"type\": \"image\", "
         "\"code\": \"void mainImage(out vec4 o, in vec2 f) { o = vec4(texelFetch(iChannel0, ivec2(f), 0).r, "
         "iSampleRate / 100000.0, iChannelResolution[0].x / 1024.0 + iChannelResolution[0].y / 8.0, 1.0); }\", "
         "\"inputs\": [{\"id\": 1, \"ctype\": \"" + ctype + "\", \"channel\": 0, \"src\": \"" + src +
         "\", \"sampler\": {\"filter\": \"linear\", \"wrap\": \"clamp\", \"vflip\": \"true\", \"srgb\": \"false\"}}], "
         "\"outputs\": []}]}}";
}

TEST(ShadertoyAudio, MusicTextureIsTheAnalysersBytesAtITime) {
  TempDir dir;
  write_tone_wav(dir / "tone.wav");
  write_file(dir / "a.json", music_json("music", "/media/a/tone.wav"));
  const RunResult r = run_marchstudio({"render", "a.json", "--media-dir", ".", "--size", "512x2", "--time", "3",
                                       "-o", "o.exr"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "o.exr");
  ASSERT_EQ(img.width, 512);
  const AudioTexels want = audio_texels(read_audio(dir / "tone.wav"), 3.0f, 1.0f / 60.0f);
  EXPECT_EQ(want[100], 255);  // the tone's bin
  EXPECT_EQ(want[300], 0);
  for (int x = 0; x < 512; ++x)
    for (int row = 0; row < 2; ++row)  // texel row 0 is the image's bottom row
      ASSERT_EQ(std::lround(img.at(x, 1 - row, 0) * 255.0f), want[row * 512 + x]) << "x " << x << " row " << row;
  EXPECT_FLOAT_EQ(img.at(0, 0, 1), 0.441f);        // iSampleRate 44100
  EXPECT_FLOAT_EQ(img.at(0, 0, 2), 0.5f + 0.25f);  // iChannelResolution (512, 2)
}

TEST(ShadertoyAudio, CorruptMissingAndMicAreOneLineErrors) {
  TempDir dir;
  write_file(dir / "bad.wav", "RIFF, but not audio");
  write_file(dir / "a.json", music_json("music", "/media/a/bad.wav"));
  RunResult r = run_marchstudio({"render", "a.json", "--media-dir", ".", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.wav"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o.png"));

  write_file(dir / "m.json", music_json("musicstream", "/media/a/gone.mp3"));
  r = run_marchstudio({"render", "m.json", "--media-dir", ".", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("audio '/media/a/gone.mp3' is not in the media directory"), std::string::npos) << r.err;
  r = run_marchstudio({"render", "m.json", "--media-dir", ".", "--missing-media", "black", "-o", "o.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("it reads as Shadertoy's audio before it loads"), std::string::npos) << r.err;

  write_file(dir / "mic.json", music_json("mic", ""));
  r = run_marchstudio({"render", "mic.json", "-o", "o2.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("mic"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ms::test
