#include "render/aov.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace ms {

const std::vector<std::string> kAovChannels = {
    "hit",   "Z",  "N.x",          "N.y",           "N.z",     "steps",   "material",
    "shadow", "ao", "shadow_steps", "reflection_steps", "sdf_evals", "step_cap"};

const std::vector<std::string> kAovNames = {"depth", "normal", "steps", "material", "shadow", "ao", "cost", "hit"};

namespace {

std::vector<std::string> channels_of(const std::string& name) {
  if (name == "depth") return {"Z"};
  if (name == "normal") return {"N.x", "N.y", "N.z"};
  if (name == "cost") return {"shadow_steps", "reflection_steps", "sdf_evals", "step_cap"};
  if (name == "steps" || name == "material" || name == "shadow" || name == "ao" || name == "hit") return {name};
  return {};
}

int channel_index(const Image& img, const std::string& name) {
  const auto it = std::find(img.channels.begin(), img.channels.end(), name);
  if (it == img.channels.end()) throw std::out_of_range("image has no channel '" + name + "'");
  return static_cast<int>(it - img.channels.begin());
}

}  // namespace

std::vector<std::string> aov_channels(const std::vector<std::string>& names) {
  std::vector<bool> want(kAovChannels.size(), false);
  want[0] = true;  // hit
  for (const std::string& n : names) {
    const std::vector<std::string> ch = channels_of(n);
    if (ch.empty())
      fail_input("unknown AOV '" + n + "'", {}, 0, "--aov",
                 "use depth, normal, steps, material, shadow, ao, cost or hit, comma-separated");
    for (const std::string& c : ch)
      want[std::find(kAovChannels.begin(), kAovChannels.end(), c) - kAovChannels.begin()] = true;
  }
  std::vector<std::string> out;
  for (size_t i = 0; i < kAovChannels.size(); ++i)
    if (want[i]) out.push_back(kAovChannels[i]);
  return out;
}

std::vector<std::pair<std::string, std::string>> aov_defines() { return {{"AOV_OUTPUTS", "1"}}; }

Image select_channels(const Image& src, const std::vector<std::string>& names) {
  std::vector<int> idx;
  for (const std::string& n : names) idx.push_back(channel_index(src, n));
  Image out;
  out.width = src.width;
  out.height = src.height;
  out.channels = names;
  const size_t npix = static_cast<size_t>(src.width) * src.height;
  out.pixels.resize(npix * names.size());
  const size_t sn = src.channels.size();
  for (size_t p = 0; p < npix; ++p)
    for (size_t c = 0; c < idx.size(); ++c) out.pixels[p * idx.size() + c] = src.pixels[p * sn + idx[c]];
  return out;
}

Image append_channels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("append_channels: sizes differ");
  Image out;
  out.width = a.width;
  out.height = a.height;
  out.channels = a.channels;
  out.channels.insert(out.channels.end(), b.channels.begin(), b.channels.end());
  const size_t npix = static_cast<size_t>(a.width) * a.height, na = a.channels.size(), nb = b.channels.size();
  out.pixels.resize(npix * (na + nb));
  for (size_t p = 0; p < npix; ++p) {
    std::copy_n(a.pixels.begin() + p * na, na, out.pixels.begin() + p * (na + nb));
    std::copy_n(b.pixels.begin() + p * nb, nb, out.pixels.begin() + p * (na + nb) + na);
  }
  return out;
}

Image aovs_from_targets(const std::vector<std::vector<float>>& targets, int width, int height, int samples) {
  Image img;
  img.width = width;
  img.height = height;
  img.channels = kAovChannels;
  const size_t npix = static_cast<size_t>(width) * height, nch = kAovChannels.size();
  img.pixels.resize(npix * nch);
  const float inv = 1.0f / static_cast<float>(samples);
  for (size_t a = 0; a < targets.size(); ++a) {
    const std::vector<float>& px = targets[a];
    for (size_t p = 0; p < npix; ++p) {
      if (a == 0) {
        img.pixels[p * nch] = px[p * 4 + 3] * inv;
      } else {
        for (size_t c = 0; c < 4; ++c) img.pixels[p * nch + 1 + (a - 1) * 4 + c] = px[p * 4 + c] * inv;
      }
    }
  }
  return img;
}

float steps_heat_position(float steps) {
  return std::clamp(std::log2(std::max(steps, 0.0f) + 1.0f) / 8.0f, 0.0f, 1.0f);
}

float depth_shade(float t, float max_dist) {
  return 1.0f - std::clamp(std::log2(1.0f + std::max(t, 0.0f)) / std::log2(1.0f + max_dist), 0.0f, 1.0f);
}

glm::vec3 heat_ramp(float x) {
  static const glm::vec3 stops[5] = {{0.0f, 0.0f, 0.25f}, {0.0f, 0.35f, 1.0f}, {0.0f, 0.85f, 0.2f},
                                     {1.0f, 0.9f, 0.0f},  {1.0f, 0.0f, 0.0f}};
  const float s = std::clamp(x, 0.0f, 1.0f) * 4.0f;
  const int i = std::min(static_cast<int>(s), 3);  // as the shader: s in [3,4] uses the last segment
  const float f = s - static_cast<float>(i);
  return stops[i] + (stops[i + 1] - stops[i]) * f;
}

}  // namespace ms
