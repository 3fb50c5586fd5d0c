// scene/writeback.h: an edit whose value equals the file's keeps the file's
// own text (`fov = 50` is not rewritten as 50.0, `[0, 1, 5]` not as floats);
// a changed value is still written.
#include <gtest/gtest.h>

#include "scene/scene.h"
#include "scene/writeback.h"

namespace ms {
namespace {

const char* kScene = R"([scene]
name = "s"
map  = "s.glsl"

[camera]
position = [0, 1.6, -5]   # eye
target   = [0.0, 0.8, 0.0]
up       = [0, 1, 0]
fov      = 50
)";

TEST(WritebackUnchanged, CameraWritebackKeepsUnchangedText) {
  Camera cam;
  cam.position = {0.0f, 1.6f, -5.0f};
  cam.target = {0.0f, 0.8f, 0.0f};
  cam.up = {0.0f, 1.0f, 0.0f};
  cam.fov_deg = 50.0f;
  EXPECT_EQ(apply_toml_edits(kScene, camera_edits(cam), "s.toml"), kScene);
}

TEST(WritebackUnchanged, AChangedValueIsStillWritten) {
  Camera cam;
  cam.position = {0.0f, 1.6f, -5.0f};
  cam.target = {0.0f, 0.8f, 0.0f};
  cam.up = {0.0f, 1.0f, 0.0f};
  cam.fov_deg = 35.0f;
  std::string want = kScene;
  want.replace(want.find("fov      = 50"), 13, "fov      = 35.0");
  EXPECT_EQ(apply_toml_edits(kScene, camera_edits(cam), "s.toml"), want);
  // A value equal as a 32-bit float counts as the same: 0.1 read and written back.
  EXPECT_EQ(apply_toml_edits("[camera]\nfov = 0.1000000001\n", {{"camera", -1, "fov", toml_float(0.1f)}}, "s.toml"),
            "[camera]\nfov = 0.1000000001\n");
  // A string or a boolean that differs is written.
  EXPECT_EQ(apply_toml_edits("[render]\ntonemap = \"aces\"\n", {{"render", -1, "tonemap", "\"reinhard\""}}, "s.toml"),
            "[render]\ntonemap = \"reinhard\"\n");
}

}  // namespace
}  // namespace ms
