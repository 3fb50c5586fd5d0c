// io/: atomic-write temporaries are recognisable, so a resumed run can clean
// up after a killed one without touching anything else.
#include <gtest/gtest.h>

#include "io/image_io.h"

namespace ms {
namespace {

TEST(ImageIoTemp, TempPathRoundTripsToItsTarget) {
  const auto tmp = temp_path_for("out/frame_0007.png", 4242);
  EXPECT_EQ(tmp, std::filesystem::path("out/.frame_0007.tmp4242.png"));
  EXPECT_EQ(temp_target_name(tmp.filename().string()), "frame_0007.png");
  EXPECT_EQ(temp_target_name(temp_path_for("a.b.exr", 1).filename().string()), "a.b.exr");
}

TEST(ImageIoTemp, OtherFilesAreNotTemporaries) {
  for (const char* name : {"frame_0007.png", ".frame.tmp.png", ".frame.tmpx12.png", "frame.tmp12.png", ".tmp12.png",
                           ".frame.tmp12.png.bak", ".hidden"})
    EXPECT_EQ(temp_target_name(name), "") << name;
}

}  // namespace
}  // namespace ms
