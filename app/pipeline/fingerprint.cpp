#include "pipeline/fingerprint.h"

#include <sstream>

#include "core/hash.h"
#include "core/version.h"
#include "io/input_file.h"

namespace ms {

std::string job_fingerprint(const LoadedInput& in, const FrameParams& fp, const ShaderSource& post,
                            const std::vector<std::string>& aovs, double fps) {
  Hash128 h;
  h.add(std::string(kSoftware) + " fingerprint 1");
  h.add(read_input_file(in.path, "input file", {}, kMaxTextInput));
  // --set changes the scene without changing the file (camera and sky are
  // uniforms, not shader text): each override's key and value.
  for (const SceneOverride& o : in.overrides) {
    std::ostringstream value;
    value << o.value;
    h.add(o.flag).add(value.str());
  }
  h.add(static_cast<std::int64_t>(in.passes.size()));
  for (const PassSource& pass : in.passes) {
    h.add(pass.name).add(pass.source.text).add(pass.output).add(static_cast<int>(pass.uniforms));
    for (const GraphInput& g : pass.inputs) {
      h.add(static_cast<int>(g.kind)).add(g.buffer).add(g.eight_bit).add(g.single_channel);
      h.add(static_cast<int>(g.sampler.filter)).add(static_cast<int>(g.sampler.wrap));
      h.add(g.sampler.vflip).add(g.sampler.srgb);
      h.add(g.image != nullptr);
      if (g.image) {
        h.add(g.image->width).add(g.image->height);
        h.add_bytes(g.image->pixels.data(), g.image->pixels.size() * sizeof(float));
      }
    }
  }
  // The environment's irradiance is uniforms, not shader text, and may come
  // from the cache (render/environment.h): what lit the image is hashed.
  if (!in.scene.sky.environment.empty())
    for (const glm::vec3& c : in.scene.sky.irradiance) h.add(c.x).add(c.y).add(c.z);
  h.add(post.text);
  h.add(fp.width).add(fp.height).add(fp.spp).add(fp.exposure).add(fp.aovs).add(fp.fused_post);
  for (const std::string& a : aovs) h.add(a);
  if (in.shadertoy) h.add(fps);  // iTimeDelta and iFrameRate; a scene sees only each frame's time
  for (float m : in.scene.shadertoy.mouse) h.add(m);
  return h.hex();
}

std::string frame_fingerprint(const std::string& job, int frame, float time) {
  return Hash128().add(job).add(frame).add(time).hex();
}

ImageMetadata frame_metadata(const std::filesystem::path& input, float time, int spp, const std::string& fingerprint,
                             std::optional<int> frame) {
  std::string description = input.filename().string() + " t=" + std::to_string(time) + " spp=" + std::to_string(spp);
  if (frame) description += " frame=" + std::to_string(*frame);
  ImageMetadata meta{{"Software", kSoftware}, {"ImageDescription", description}};
  add_fingerprint(meta, fingerprint);
  return meta;
}

}  // namespace ms
