// The viewer's sound: a Shadertoy music input played on an ALSA device in
// step with the viewer's time, the clip looping as its analyser texture
// does (render/audio_texture.h). libasound is dlopen'd when a shader with
// music opens, so the viewer starts without it; no library, no device or
// `view --audio-device none` leaves the viewer silent, and the texture
// stays what `render` gives at the same time either way.
//
//   AudioOut out;
//   std::string why = out.open("default", clip);   // empty: playing
//   out.update(state.time, state.paused);          // once a frame
#pragma once
#include <memory>
#include <string>

#include "io/audio.h"

namespace ms::live {

class AudioOut {
 public:
  AudioOut() = default;
  ~AudioOut();
  AudioOut(const AudioOut&) = delete;
  AudioOut& operator=(const AudioOut&) = delete;

  // Opens `device` (an ALSA PCM name: "default", "null", "hw:0"; "none"
  // opens nothing) for `clip`, mono float at its rate. Returns why it is
  // silent, or empty when it plays. A second open replaces the first.
  std::string open(const std::string& device, std::shared_ptr<const AudioClip> clip);
  void close();
  bool playing() const { return pcm_ != nullptr; }

  // Once a frame: writes the clip up to 0.15 s past `time`. When what is
  // written has fallen more than 0.1 s behind `time` or runs 0.3 s ahead (a
  // seek, Home, a slow frame), or after a pause, it restarts from `time`.
  void update(double time, bool paused);

  // Samples written so far and restarts (for the log and tests).
  long long written() const { return written_; }
  int restarts() const { return restarts_; }

 private:
  void* pcm_ = nullptr;  // snd_pcm_t*
  std::shared_ptr<const AudioClip> clip_;
  long long next_ = 0;   // the clip sample (unwrapped) written next
  bool stopped_ = true;  // nothing queued: the next update starts at its time
  long long written_ = 0;
  int restarts_ = 0;
};

}  // namespace ms::live
