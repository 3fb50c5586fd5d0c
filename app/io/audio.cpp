#include "io/audio.h"

#include <dlfcn.h>
#include <sndfile.h>  // types only: the functions come through dlopen

#include <cmath>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// libsndfile's entry points, opened once for the process.
struct SndFile {
  SNDFILE* (*open)(const char*, int, SF_INFO*) = nullptr;
  sf_count_t (*readf_float)(SNDFILE*, float*, sf_count_t) = nullptr;
  int (*close)(SNDFILE*) = nullptr;
  const char* (*strerror)(SNDFILE*) = nullptr;
};

const SndFile& sndfile() {
  static const SndFile lib = [] {
    SndFile s;
    void* h = ::dlopen("libsndfile.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!h) fail_system("cannot load libsndfile (libsndfile.so.1) to decode audio", "");
    s.open = reinterpret_cast<decltype(s.open)>(::dlsym(h, "sf_open"));
    s.readf_float = reinterpret_cast<decltype(s.readf_float)>(::dlsym(h, "sf_readf_float"));
    s.close = reinterpret_cast<decltype(s.close)>(::dlsym(h, "sf_close"));
    s.strerror = reinterpret_cast<decltype(s.strerror)>(::dlsym(h, "sf_strerror"));
    if (!s.open || !s.readf_float || !s.close || !s.strerror) fail_system("libsndfile.so.1 lacks sf_open", "");
    return s;
  }();
  return lib;
}

}  // namespace

float downmix_to_mono(const float* f, int channels) {
  switch (channels) {
    case 1: return f[0];
    case 2: return 0.5f * (f[0] + f[1]);
    case 4: return 0.25f * (f[0] + f[1] + f[2] + f[3]);
    case 6: return std::sqrt(0.5f) * (f[0] + f[1]) + f[2] + 0.5f * (f[4] + f[5]);
    default: return f[0];
  }
}

AudioClip read_audio(const fs::path& file) {
  const std::string problem = input_file_problem(file);
  if (!problem.empty()) fail_input("cannot read the audio file: " + problem, file.string());
  const SndFile& sf = sndfile();
  SF_INFO info{};
  SNDFILE* h = sf.open(file.c_str(), SFM_READ, &info);
  if (!h) fail_input(std::string("cannot decode the audio file: ") + sf.strerror(nullptr), file.string());
  const std::unique_ptr<SNDFILE, int (*)(SNDFILE*)> closer(h, sf.close);
  AudioClip clip;
  clip.sample_rate = info.samplerate;
  const int ch = info.channels;
  if (ch <= 0 || info.samplerate <= 0 || info.frames <= 0) fail_input("the audio file holds no samples", file.string());
  // The header's frame count, checked before the samples are allocated (a
  // FLAC can claim 2^36); a stream that decodes past its claim stops at
  // the budget too.
  const auto mono_bytes = [](double frames) { return static_cast<double>(sizeof(float)) * frames; };
  check_input_memory(mono_bytes(static_cast<double>(info.frames)),
                     "a clip of " + std::to_string(info.frames) + " frames", file.string(), "a shorter clip");
  std::vector<float> block(static_cast<size_t>(4096) * ch);
  clip.mono.reserve(static_cast<size_t>(info.frames));
  for (;;) {
    const sf_count_t n = sf.readf_float(h, block.data(), 4096);
    if (n <= 0) break;
    check_input_memory(mono_bytes(static_cast<double>(clip.mono.size() + static_cast<size_t>(n))),
                       "a clip of more than " + std::to_string(clip.mono.size()) + " frames", file.string(),
                       "a shorter clip");
    for (sf_count_t i = 0; i < n; ++i) {
      const float v = downmix_to_mono(block.data() + i * ch, ch);
      clip.mono.push_back(std::isfinite(v) ? v : 0.0f);
    }
  }
  if (clip.mono.empty()) fail_input("the audio file holds no samples", file.string());
  return clip;
}

}  // namespace ms
