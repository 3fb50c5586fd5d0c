// io/direct_codec: PNG and EXR written by libpng and OpenEXR hold what
// OpenImageIO's own writer (the image module) would have written: the same
// pixels bit for bit once read back, and the metadata under the same names.
// And the image module itself is found, or its absence is one clear error.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "files.h"
#include "io/direct_codec.h"
#include "io/image_backend.h"
#include "io/image_io.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

class DirectCodec : public ::testing::Test {
 protected:
  test::TempDir tmp;
  const fs::path dir = tmp.path();
};

// Every value that rounds differently on either side of a level, the ends,
// the out-of-range and the non-finite.
std::vector<float> tricky_values() {
  std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, 2.0f, 1e30f, -1e30f,
                          std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()};
  for (int k = 0; k <= 256; ++k)
    for (float d : {-0.5f, -0.25f, 0.0f, 0.25f, 0.5f}) {
      const float x = (k + d) / 255.0f;
      v.push_back(x);
      v.push_back(std::nextafter(x, 2.0f));
      v.push_back(std::nextafter(x, -2.0f));
    }
  return v;
}

Image ramp(std::vector<std::string> channels, const std::vector<float>& values) {
  Image img;
  img.channels = std::move(channels);
  const int n = img.nchannels();
  img.width = 64;
  img.height = static_cast<int>((values.size() + 64 * n - 1) / (64 * n));
  img.pixels.assign(static_cast<size_t>(img.width) * img.height * n, 0.25f);
  std::copy(values.begin(), values.end(), img.pixels.begin());
  return img;
}

TEST(DirectCodecBytes, RoundsAsOpenImageIOConverts) {
  const std::vector<float> v = tricky_values();
  const Image q = image_backend().quantize_8bit(ramp({"Y"}, v));
  for (size_t i = 0; i < v.size(); ++i)
    ASSERT_EQ(to_display_byte(v[i]), std::lround(q.pixels[i] * 255.0f)) << "value " << v[i] << " (index " << i << ")";
}

void expect_same_file(const fs::path& direct, const fs::path& oiio) {
  const Image a = read_image(direct), b = read_image(oiio);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const bool both_nan = std::isnan(a.pixels[i]) && std::isnan(b.pixels[i]);
    ASSERT_TRUE(both_nan || a.pixels[i] == b.pixels[i]) << direct << " value " << i;
  }
  const ImageInfo ia = read_image_info(direct), ib = read_image_info(oiio);
  EXPECT_EQ(ia.format, ib.format);
  EXPECT_EQ(ia.pixel_type, ib.pixel_type);
  EXPECT_EQ(ia.fingerprint, ib.fingerprint);
  EXPECT_FALSE(ia.fingerprint.empty());
  auto attr = [](const ImageInfo& info, const std::string& key) {
    for (const auto& [k, v] : info.attributes)
      if (k == key) return v;
    return std::string("(absent)");
  };
  for (const char* key : {"Software", "ImageDescription", "oiio:ColorSpace", "marchstudio:fingerprint"})
    EXPECT_EQ(attr(ia, key), attr(ib, key)) << direct << ": " << key;
}

TEST_F(DirectCodec, PngMatchesOpenImageIOsPng) {
  ImageMetadata meta{{"Software", "marchstudio test"}, {"ImageDescription", "a ramp"}};
  add_fingerprint(meta, "00112233445566778899aabbccddeeff");
  for (const std::vector<std::string>& ch :
       std::vector<std::vector<std::string>>{{"R", "G", "B", "A"}, {"R", "G", "B"}, {"Y"}}) {
    const Image img = ramp(ch, tricky_values());
    write_direct(img, dir / "direct.png", ImageFormat::png, meta);
    image_backend().write(img, dir / "oiio.png", ImageFormat::png, meta);
    expect_same_file(dir / "direct.png", dir / "oiio.png");
  }
}

TEST_F(DirectCodec, ExrMatchesOpenImageIOsExrWithAovChannels) {
  ImageMetadata meta{{"Software", "marchstudio test"}, {"ImageDescription", "AOVs"}};
  add_fingerprint(meta, "ffeeddccbbaa99887766554433221100");
  const Image img = ramp({"R", "G", "B", "A", "Z", "N.x", "N.y", "N.z", "steps"}, tricky_values());
  write_direct(img, dir / "direct.exr", ImageFormat::exr, meta);
  image_backend().write(img, dir / "oiio.exr", ImageFormat::exr, meta);
  expect_same_file(dir / "direct.exr", dir / "oiio.exr");
}

TEST_F(DirectCodec, AFullDiskLeavesNothing) {
  // A file size limit fails the writes as a full disk would, with SIGXFSZ
  // ignored as main() does. (Not in a forked child: OpenEXR's thread pool
  // would not be there.)
  std::vector<float> noise(64 * 64 * 3);  // incompressible: well over the limit in either format
  unsigned h = 12345;
  for (float& x : noise) x = static_cast<float>((h = h * 1103515245u + 12345u) >> 8 & 255) / 255.0f;
  const Image img = ramp({"R", "G", "B"}, noise);
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  for (const char* name : {"big.png", "big.exr"}) {
    const rlimit lim{512, old.rlim_max};
    setrlimit(RLIMIT_FSIZE, &lim);
    Exit code = Exit::ok;
    try {
      write_direct(img, dir / name, image_format_for(dir / name), {});
    } catch (const Error& e) {
      code = e.code();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    EXPECT_EQ(code, Exit::system) << name;
    EXPECT_FALSE(fs::exists(dir / name)) << name;
    for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
  }
  std::signal(SIGXFSZ, old_handler);
}

}  // namespace
}  // namespace ms
