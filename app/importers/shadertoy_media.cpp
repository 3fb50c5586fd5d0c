#include "importers/shadertoy_media.h"

#include <array>

namespace ms {
namespace {

// From the site's texture list (names and hashes are public: every
// exported shader carries them); single_channel per REFERENCES.md.
constexpr std::array<ShadertoyMedia, 8> kMedia = {{
    {"0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5", "Gray Noise Medium", true, 256, false},
    {"0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d", "Gray Noise Small", true, 64, false},
    {"f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb", "RGBA Noise Medium", false, 256, false},
    {"3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0", "RGBA Noise Small", false, 64, false},
    {"85a6d68622b36995ccb98a89bbb119edf167c914660e4450d313de049320005c", "Bayer", true, 0, false},
    {"ad56fba948dfba9ae698198c109e71f118a54d209c0ea50d77ea546abad89c57", "Pebbles", true, 0, false},
    {"27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04", "Gray Noise 3D", true, 32, true},
    {"aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa", "RGBA Noise 3D", false, 32, true},
}};

}  // namespace

const ShadertoyMedia* find_shadertoy_media(std::string_view src) {
  const size_t slash = src.find_last_of('/');
  std::string_view name = slash == std::string_view::npos ? src : src.substr(slash + 1);
  name = name.substr(0, name.find('.'));
  for (const ShadertoyMedia& m : kMedia)
    if (m.hash == name) return &m;
  return nullptr;
}

}  // namespace ms
