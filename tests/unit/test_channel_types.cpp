// Typed channels: the sampler type each input kind is declared
// with, the volume entries of Shadertoy's media table, a volume input's
// sampler defaults, and the volume stand-in's documented formula.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "pipeline/project_passes.h"
#include "importers/project_json.h"
#include "importers/shadertoy_media.h"

namespace ms {
namespace {

TEST(ProjectChannelTypes, SamplerTypeFollowsTheInputKind) {
  EXPECT_EQ(channel_type(InputKind::volume), ChannelType::tex3d);
  EXPECT_EQ(channel_type(InputKind::cubemap), ChannelType::cube);
  for (InputKind k : {InputKind::none, InputKind::buffer, InputKind::texture, InputKind::keyboard})
    EXPECT_EQ(channel_type(k), ChannelType::tex2d);
  EXPECT_STREQ(glsl_sampler_type(ChannelType::tex2d), "sampler2D");
  EXPECT_STREQ(glsl_sampler_type(ChannelType::cube), "samplerCube");
  EXPECT_STREQ(glsl_sampler_type(ChannelType::tex3d), "sampler3D");
}

TEST(ProjectChannelTypes, ShadertoysTwoNoiseVolumes) {
  const ShadertoyMedia* gray =
      find_shadertoy_media("/media/a/27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04.bin");
  const ShadertoyMedia* rgba =
      find_shadertoy_media("/media/a/aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa.bin");
  ASSERT_TRUE(gray && rgba);
  EXPECT_TRUE(gray->volume && gray->single_channel && gray->noise_size == 32);
  EXPECT_TRUE(rgba->volume && !rgba->single_channel && rgba->noise_size == 32);
  EXPECT_FALSE(find_shadertoy_media("0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png")->volume);
}

TEST(ProjectChannelTypes, AVolumeInputTakesATexturesSamplerDefaults) {
  const ShaderProject p = load_shadertoy_json(
      R"({"Shader": {"renderpass": [{"type": "image", "code": "", "inputs": [
          {"ctype": "volume", "channel": 2, "src": "/media/a/x.bin"},
          {"type": "volume", "channel": 3, "filepath": "/media/a/y.bin", "sampler": {"filter": "nearest", "wrap": "clamp"}}]}]}})",
      "v.json");
  const ProjectInput& a = p.image().inputs[2];
  EXPECT_EQ(a.kind, InputKind::volume);
  EXPECT_EQ(a.src, "/media/a/x.bin");
  EXPECT_EQ(a.sampler.filter, TexFilter::mipmap);
  EXPECT_EQ(a.sampler.wrap, TexWrap::repeat);
  const ProjectInput& b = p.image().inputs[3];
  EXPECT_EQ(b.src, "/media/a/y.bin");
  EXPECT_EQ(b.sampler.filter, TexFilter::nearest);
  EXPECT_EQ(b.sampler.wrap, TexWrap::clamp);
}

// The formula as documented: bytes of the PCG hash of the voxel's index.
TEST(ProjectChannelTypes, VolumeStandInIsThePcgHashOfEachVoxel) {
  // pcg_hash(0) = 0x07bb2fe2, worked out from the formula apart from this code.
  EXPECT_EQ(volume_noise_byte(0, 0, 0, 0, 32), 0xe2);
  EXPECT_EQ(volume_noise_byte(0, 0, 0, 3, 32), 0x07);
  const ShadertoyMedia* rgba = find_shadertoy_media("aea6b99da1d53055107966b59ac5444fc8bc7b3ce2d0bbb6a4a3cbae1d97f3aa");
  const Volume v = volume_standin(*rgba, MissingMedia::noise);
  ASSERT_EQ(v.size, 32);
  ASSERT_EQ(v.channels, 4);
  ASSERT_EQ(v.voxels.size(), 32u * 32 * 32 * 4);
  const size_t at = ((5u * 32 + 6) * 32 + 7) * 4;  // voxel (7, 6, 5)
  for (int c = 0; c < 4; ++c) EXPECT_EQ(v.voxels[at + c], volume_noise_byte(7, 6, 5, c, 32));
  std::set<std::uint8_t> levels(v.voxels.begin(), v.voxels.end());
  EXPECT_GT(levels.size(), 250u);  // noise, not a constant
  const Volume black = volume_standin(*rgba, MissingMedia::black);
  EXPECT_EQ(black.size, 1);
  EXPECT_EQ(black.voxels, (std::vector<std::uint8_t>{0, 0, 0, 255}));
}

}  // namespace
}  // namespace ms
