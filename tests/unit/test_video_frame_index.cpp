// Which frame of a video input shows at a time (io/video_input.h):
// floor(fmod(t, duration) x fps), frame 0 before time 0, the last frame held
// to the end of the loop, and t = n / fps as a float showing frame n.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/video_input.h"

namespace ms {
namespace {

VideoInfo clip(double fps, double duration) {
  VideoInfo v;
  v.width = v.height = 2;
  v.fps = fps;
  v.duration = duration;
  v.frames = std::max(1L, std::lround(duration * fps));
  return v;
}

TEST(VideoFrameIndex, LoopsFromTheStart) {
  const VideoInfo v = clip(4.0, 2.0);  // 8 frames
  EXPECT_EQ(video_frame_index(v, 0.0), 0);
  EXPECT_EQ(video_frame_index(v, 0.249), 0);
  EXPECT_EQ(video_frame_index(v, 0.25), 1);
  EXPECT_EQ(video_frame_index(v, 1.99), 7);
  EXPECT_EQ(video_frame_index(v, 2.0), 0);
  EXPECT_EQ(video_frame_index(v, 9.5), 6);
  EXPECT_EQ(video_frame_index(v, -1.0), 0);
}

TEST(VideoFrameIndex, FloatTimesOfFramesShowThoseFrames) {
  const VideoInfo v = clip(30000.0 / 1001.0, 10.01);  // NTSC rate
  for (long n = 0; n < v.frames; ++n) {
    const float t = static_cast<float>(static_cast<double>(n) / v.fps);  // iTime is a float
    ASSERT_EQ(video_frame_index(v, t), n) << "t " << t;
  }
}

TEST(VideoFrameIndex, TheLastFrameHoldsToTheLoopsEnd) {
  const VideoInfo v = clip(4.0, 2.1);  // 8 frames (round(8.4)); the period is still 2.1 s
  EXPECT_EQ(video_frame_index(v, 2.05), 7);
  EXPECT_EQ(video_frame_index(v, 2.1), 0);
}

}  // namespace
}  // namespace ms
