// The lean GPU bench has neither libsndfile nor kissfft: a shader with an
// audio input is refused in one line (io/audio.h), so no clip ever reaches
// the analyser, which stays empty here.
#include "core/error.h"
#include "io/audio.h"
#include "render/audio_texture.h"

namespace ms {

float downmix_to_mono(const float* frame, int) { return frame[0]; }

AudioClip read_audio(const std::filesystem::path& file) {
  fail_input("the GPU bench does not read audio inputs (use the full marchstudio)", file.string());
}

float audio_sample_at(const AudioClip&, long long) { return 0.0f; }

AudioTexels audio_texels(const AudioClip&, double, double) { return AudioTexels{}; }

}  // namespace ms
