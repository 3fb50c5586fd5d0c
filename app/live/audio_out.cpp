#include "live/audio_out.h"

#include <dlfcn.h>

#include <alsa/asoundlib.h>  // types and constants only: the functions come through dlopen

#include <algorithm>
#include <cmath>
#include <vector>

namespace ms::live {
namespace {

struct Alsa {
  decltype(&snd_pcm_open) open = nullptr;
  decltype(&snd_pcm_set_params) set_params = nullptr;
  decltype(&snd_pcm_writei) writei = nullptr;
  decltype(&snd_pcm_avail_update) avail = nullptr;
  decltype(&snd_pcm_delay) delay = nullptr;
  decltype(&snd_pcm_drop) drop = nullptr;
  decltype(&snd_pcm_prepare) prepare = nullptr;
  decltype(&snd_pcm_recover) recover = nullptr;
  decltype(&snd_pcm_close) close = nullptr;
  decltype(&snd_strerror) strerror = nullptr;
  bool ok = false;
};

void quiet(const char*, int, const char*, int, const char*, ...) {}  // ALSA would print to stderr

const Alsa& alsa() {
  static const Alsa a = [] {
    Alsa x;
    void* h = ::dlopen("libasound.so.2", RTLD_NOW | RTLD_LOCAL);
    if (!h) return x;
    auto sym = [h](auto& fn, const char* name) { fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(::dlsym(h, name)); };
    sym(x.open, "snd_pcm_open");
    sym(x.set_params, "snd_pcm_set_params");
    sym(x.writei, "snd_pcm_writei");
    sym(x.avail, "snd_pcm_avail_update");
    sym(x.delay, "snd_pcm_delay");
    sym(x.drop, "snd_pcm_drop");
    sym(x.prepare, "snd_pcm_prepare");
    sym(x.recover, "snd_pcm_recover");
    sym(x.close, "snd_pcm_close");
    sym(x.strerror, "snd_strerror");
    decltype(&snd_lib_error_set_handler) set_handler = nullptr;
    sym(set_handler, "snd_lib_error_set_handler");
    if (set_handler) set_handler(quiet);
    x.ok = x.open && x.set_params && x.writei && x.avail && x.delay && x.drop && x.prepare && x.recover && x.close &&
           x.strerror;
    return x;
  }();
  return a;
}

snd_pcm_t* pcm(void* p) { return static_cast<snd_pcm_t*>(p); }

}  // namespace

AudioOut::~AudioOut() { close(); }

void AudioOut::close() {
  if (pcm_) {
    alsa().drop(pcm(pcm_));
    alsa().close(pcm(pcm_));
  }
  pcm_ = nullptr;
  stopped_ = true;
}

std::string AudioOut::open(const std::string& device, std::shared_ptr<const AudioClip> clip) {
  close();
  clip_ = std::move(clip);
  if (device == "none") return "--audio-device none";
  if (!clip_ || clip_->mono.empty() || clip_->sample_rate <= 0) return "nothing to play";
  const Alsa& a = alsa();
  if (!a.ok) return "libasound.so.2 is not installed";
  snd_pcm_t* p = nullptr;
  int e = a.open(&p, device.c_str(), SND_PCM_STREAM_PLAYBACK, SND_PCM_NONBLOCK);
  if (e < 0) return "ALSA device '" + device + "': " + a.strerror(e);
  e = a.set_params(p, SND_PCM_FORMAT_FLOAT_LE, SND_PCM_ACCESS_RW_INTERLEAVED, 1,
                   static_cast<unsigned>(clip_->sample_rate), 1, 200000);  // 0.2 s of latency at most
  if (e < 0) {
    a.close(p);
    return "ALSA device '" + device + "': " + a.strerror(e);
  }
  pcm_ = p;
  return {};
}

void AudioOut::update(double time, bool paused) {
  if (!pcm_) return;
  const Alsa& a = alsa();
  if (paused) {
    if (!stopped_) {
      a.drop(pcm(pcm_));
      a.prepare(pcm(pcm_));
      stopped_ = true;
    }
    return;
  }
  const double rate = clip_->sample_rate;
  const long long at = static_cast<long long>(std::floor(std::max(time, 0.0) * rate));
  // Written ahead of `time` by at most 0.15 s: the device plays at its rate,
  // we follow the viewer's clock. Behind it or far ahead (a seek, Home, a
  // slow frame): start again at `time`.
  if (stopped_ || next_ < at - static_cast<long long>(0.1 * rate) || next_ > at + static_cast<long long>(0.3 * rate)) {
    if (!stopped_) ++restarts_;
    a.drop(pcm(pcm_));
    a.prepare(pcm(pcm_));
    next_ = at;
    stopped_ = false;
  }
  snd_pcm_sframes_t room = a.avail(pcm(pcm_));
  if (room < 0) {
    a.recover(pcm(pcm_), static_cast<int>(room), 1);
    room = a.avail(pcm(pcm_));
    if (room < 0) return;
  }
  const long long n = std::min<long long>(room, at + static_cast<long long>(0.15 * rate) - next_);
  if (n <= 0) return;
  std::vector<float> buf(static_cast<size_t>(n));
  const long long len = static_cast<long long>(clip_->mono.size());
  for (long long i = 0; i < n; ++i) buf[static_cast<size_t>(i)] = clip_->mono[static_cast<size_t>((next_ + i) % len)];
  const snd_pcm_sframes_t w = a.writei(pcm(pcm_), buf.data(), static_cast<snd_pcm_uframes_t>(n));
  if (w > 0) {
    next_ += w;
    written_ += w;
  } else if (w < 0) {
    a.recover(pcm(pcm_), static_cast<int>(w), 1);
  }
}

}  // namespace ms::live
