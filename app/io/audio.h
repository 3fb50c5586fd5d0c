// Audio files as mono samples: what a Shadertoy music input plays.
// Decoded by libsndfile (WAV, FLAC, OGG/Vorbis, Opus, MP3 with Debian's
// 1.2), which is dlopen'd on the first read so that runs without audio
// never load it or its codecs.
//
//   AudioClip a = read_audio("song.wav");   // throws bad_input naming the file
//   float s = a.mono[i];                    // a.sample_rate samples a second
#pragma once
#include <filesystem>
#include <vector>

namespace ms {

struct AudioClip {
  int sample_rate = 0;
  std::vector<float> mono;  // every frame down-mixed as Web Audio's analyser does
};

// Web Audio's "speakers" down-mix to mono of one frame of `channels`
// samples: mono as is, stereo 0.5 (L + R), quad 0.25 (L + R + SL + SR),
// 5.1 sqrt(1/2) (L + R) + C + 0.5 (SL + SR) (LFE dropped); any other
// layout is discrete: its first channel.
float downmix_to_mono(const float* frame, int channels);

// The whole file, decoded. A file libsndfile cannot read (corrupt, not
// audio, no frames) is bad_input naming it; libsndfile missing is system.
AudioClip read_audio(const std::filesystem::path& file);

}  // namespace ms
