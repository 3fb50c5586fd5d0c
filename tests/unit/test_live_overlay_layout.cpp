// live/overlay.h help_rect(): the key help never covers the status box
// (samples 3 / 8, paused, the debug view) at the window's top right.
#include <gtest/gtest.h>

#include "live/overlay.h"

namespace ms::live {
namespace {

// The status box as draw_overlay() places it: 10 px from the top right.
OverlayRect status_box(float width, float w, float h) { return {width - 10.0f - w, 10.0f, w, h}; }

TEST(LiveOverlayLayout, CentredWhenNothingIsInTheWay) {
  const OverlayRect r = help_rect(1280.0f, 720.0f, {}, 400.0f, 300.0f);
  EXPECT_FLOAT_EQ(r.x, 440.0f);
  EXPECT_FLOAT_EQ(r.y, 210.0f);
  // A status box far from the centre does not move it.
  EXPECT_FLOAT_EQ(help_rect(1280.0f, 720.0f, status_box(1280.0f, 200.0f, 40.0f), 400.0f, 300.0f).y, 210.0f);
}

TEST(LiveOverlayLayout, NeverOverTheStatusBox) {
  for (const float width : {320.0f, 480.0f, 640.0f, 960.0f, 1280.0f})
    for (const float height : {180.0f, 270.0f, 360.0f, 540.0f, 720.0f})
      for (const float status_h : {20.0f, 40.0f, 120.0f}) {
        const OverlayRect status = status_box(width, 220.0f, status_h);
        const OverlayRect r = help_rect(width, height, status, 360.0f, 330.0f);
        EXPECT_FALSE(r.overlaps(status)) << width << "x" << height << " status height " << status_h << ": help at ("
                                         << r.x << ", " << r.y << ")";
        EXPECT_FLOAT_EQ(r.w, 360.0f);
        EXPECT_FLOAT_EQ(r.h, 330.0f);
      }
}

TEST(LiveOverlayLayout, TheCentredHelpCoversTheBoxInASmallWindow) {
  // The case the layout exists for: at 640x360 centred help reaches the top right.
  const OverlayRect status = status_box(640.0f, 220.0f, 40.0f);
  const OverlayRect centred{0.5f * (640.0f - 360.0f), 0.5f * (360.0f - 330.0f), 360.0f, 330.0f};
  EXPECT_TRUE(centred.overlaps(status));
  EXPECT_FALSE(help_rect(640.0f, 360.0f, status, 360.0f, 330.0f).overlaps(status));
}

}  // namespace
}  // namespace ms::live
