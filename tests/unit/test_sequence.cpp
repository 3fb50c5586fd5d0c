// Image sequences: frame ranges (cli/frame_flags.h) and patterns parse or
// fail clearly, shards partition the range exactly, resume tells complete
// frames from broken ones, stale temporaries go, and the writer queue is
// bounded and reports its errors.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <unistd.h>

#include "cli/frame_flags.h"
#include "core/error.h"
#include "io/frame_writer.h"
#include "io/image_io.h"
#include "io/sequence.h"
#include "files.h"

namespace fs = std::filesystem;

namespace {

using ms::test::TempDir;

ms::ErrorInfo error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ms::Error& e) {
    return e.info();
  }
  ADD_FAILURE() << "no error";
  return {};
}

ms::Image gray(int w, int h, float v) {
  ms::Image img;
  img.width = w;
  img.height = h;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.assign(static_cast<size_t>(w) * h * 4, v);
  return img;
}

TEST(FrameRange, Parses) {
  EXPECT_EQ(ms::parse_frame_range("0..59").first, 0);
  EXPECT_EQ(ms::parse_frame_range("0..59").last, 59);
  EXPECT_EQ(ms::parse_frame_range("12..12").count(), 1);
  EXPECT_EQ(ms::parse_frame_range("7").last, 7);
}

TEST(FrameRange, BadRangesAreClearErrors) {
  for (const char* bad : {"5..2", "-1..4", "0..-3", "", "a..b", "1...3", "0..100000000", "1-5"}) {
    const ms::ErrorInfo e = error_of([&] { ms::parse_frame_range(bad); });
    EXPECT_EQ(e.code, ms::Exit::bad_input) << bad;
    EXPECT_EQ(e.key, "--frames") << bad;
  }
  EXPECT_NE(error_of([] { ms::parse_frame_range("5..2"); }).what.find("ends before it starts"), std::string::npos);
  EXPECT_NE(error_of([] { ms::parse_frame_range("-1..4"); }).what.find("negative"), std::string::npos);
}

TEST(Shard, ParsesAndRejects) {
  const ms::Shard s = ms::parse_shard("2/4");
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 4);
  for (const char* bad : {"4/4", "-1/4", "0/0", "1", "a/b", "1/-2"})
    EXPECT_EQ(error_of([&] { ms::parse_shard(bad); }).key, "--shard") << bad;
  EXPECT_EQ(error_of([] { ms::parse_shard_mode("random"); }).key, "--shard-mode");
}

// The union of all shards is the range, each frame exactly once, for both
// modes and awkward sizes (more shards than frames, uneven splits).
TEST(Shard, ShardsPartitionTheRange) {
  for (ms::ShardMode mode : {ms::ShardMode::stride, ms::ShardMode::chunk})
    for (const ms::FrameRange r : {ms::FrameRange{0, 59}, ms::FrameRange{5, 21}, ms::FrameRange{3, 3}})
      for (int n : {1, 2, 3, 4, 7, 16, 61}) {
        std::multiset<int> seen;
        std::size_t largest = 0, smallest = SIZE_MAX;
        for (int i = 0; i < n; ++i) {
          const std::vector<int> f = ms::shard_frames(r, {i, n}, mode);
          EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
          seen.insert(f.begin(), f.end());
          largest = std::max(largest, f.size());
          smallest = std::min(smallest, f.size());
        }
        ASSERT_EQ(seen.size(), static_cast<size_t>(r.count())) << "mode " << int(mode) << " n " << n;
        for (int f = r.first; f <= r.last; ++f) EXPECT_EQ(seen.count(f), 1u) << f;
        EXPECT_LE(largest - smallest, 1u) << "balanced";
      }
}

TEST(Shard, StrideAndChunkOrder) {
  EXPECT_EQ(ms::shard_frames({0, 9}, {1, 4}, ms::ShardMode::stride), (std::vector<int>{1, 5, 9}));
  EXPECT_EQ(ms::shard_frames({0, 9}, {1, 4}, ms::ShardMode::chunk), (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(ms::shard_frames({10, 25}, {3, 4}, ms::ShardMode::chunk), (std::vector<int>{22, 23, 24, 25}));
}

TEST(FramePattern, Expands) {
  EXPECT_EQ(ms::FramePattern("out/frame_%04d.png").path(7), fs::path("out/frame_0007.png"));
  EXPECT_EQ(ms::FramePattern("f%d.exr").path(123), fs::path("f123.exr"));
  EXPECT_EQ(ms::FramePattern("a%%b_%03d.png").path(12345), fs::path("a%b_12345.png"));
  EXPECT_TRUE(ms::has_frame_field("x_%04d.png"));
  EXPECT_FALSE(ms::has_frame_field("100%%.png"));
}

TEST(FramePattern, BadPatternsAreClearErrors) {
  for (const char* bad : {"out/frame.png", "f_%d_%d.png", "out%d/f.png", "f_%s.png", "f_%4d.png", "f_%.png",
                          "100%%.png"}) {
    const ms::ErrorInfo e = error_of([&] { ms::FramePattern p(bad); });
    EXPECT_EQ(e.code, ms::Exit::bad_input) << bad;
    EXPECT_EQ(e.key, "-o") << bad;
  }
  EXPECT_NE(error_of([] { ms::FramePattern p("out/frame.png"); }).what.find("no frame field"), std::string::npos);
}

TEST(Resume, CompleteFramesAreTold) {
  TempDir dir;
  const fs::path good = dir.path() / "good.png", cut = dir.path() / "cut.png";
  ms::write_image(gray(32, 16, 0.5f), good);
  EXPECT_TRUE(ms::frame_is_complete(good, 32, 16));
  std::string why;
  EXPECT_FALSE(ms::frame_is_complete(good, 64, 16, &why));
  EXPECT_NE(why.find("64x16 expected"), std::string::npos) << why;
  EXPECT_FALSE(ms::frame_is_complete(dir.path() / "none.png", 32, 16, &why));
  EXPECT_EQ(why, "missing");
  // A copy cut short: the header is there, the pixels are not.
  const auto size = fs::file_size(good);
  fs::copy_file(good, cut);
  fs::resize_file(cut, size / 2);
  EXPECT_FALSE(ms::frame_is_complete(cut, 32, 16, &why));
  // EXR too.
  const fs::path exr = dir.path() / "f.exr";
  ms::write_image(gray(8, 8, 2.0f), exr);
  EXPECT_TRUE(ms::frame_is_complete(exr, 8, 8));
}

TEST(Resume, StaleTempsOfOwnFramesAreRemoved) {
  TempDir dir;
  const ms::FramePattern pattern((dir.path() / "f_%03d.png").string());
  for (const char* name : {".f_001.tmp4242.png", ".f_002.tmp17.png", ".f_009.tmp5.png", ".f_001.tmpx.png",
                           "f_001.png", ".other.tmp1.png"})
    std::ofstream(dir.path() / name) << "x";
  const auto removed = ms::remove_stale_temps(pattern, {1, 2, 3});
  EXPECT_EQ(removed.size(), 2u);
  EXPECT_FALSE(fs::exists(dir.path() / ".f_001.tmp4242.png"));
  EXPECT_FALSE(fs::exists(dir.path() / ".f_002.tmp17.png"));
  EXPECT_TRUE(fs::exists(dir.path() / ".f_009.tmp5.png")) << "another shard's frame";
  EXPECT_TRUE(fs::exists(dir.path() / ".f_001.tmpx.png")) << "not write_image's name";
  EXPECT_TRUE(fs::exists(dir.path() / "f_001.png"));
  EXPECT_TRUE(fs::exists(dir.path() / ".other.tmp1.png"));
}

// The queue holds at most `capacity` frames: the producer blocks until the
// writer takes one, and everything pushed is written, in order.
TEST(FrameWriter, IsBoundedAndWritesEverything) {
  std::atomic<bool> release{false};
  std::vector<int> order;
  std::mutex m;
  {
    ms::FrameWriter writer(
        2, {},
        [&](const ms::WriteJob& j) {
          while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
          std::lock_guard<std::mutex> lock(m);
          order.push_back(j.frame);
        });
    writer.push({0, {}, {}, {}});  // taken by the writer, which then blocks
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    writer.push({1, {}, {}, {}});
    writer.push({2, {}, {}, {}});  // the queue is now full
    std::atomic<bool> pushed{false};
    std::thread producer([&] {
      writer.push({3, {}, {}, {}});
      pushed = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_FALSE(pushed) << "push must block while the queue is full";
    release = true;
    producer.join();
    EXPECT_TRUE(pushed);
    writer.finish();
    EXPECT_EQ(writer.written(), 4);
  }
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3}));
}

TEST(FrameWriter, ErrorReachesTheProducer) {
  ms::FrameWriter writer(4, {}, [](const ms::WriteJob& j) {
    if (j.frame == 1) ms::fail_system("disk full", j.path.string());
  });
  writer.push({0, {}, "a", {}});
  writer.push({1, {}, "b", {}});
  try {
    writer.finish();
    FAIL() << "finish must rethrow the write error";
  } catch (const ms::Error& e) {
    EXPECT_EQ(e.code(), ms::Exit::system);
    EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos);
  }
  EXPECT_THROW(writer.push({2, {}, "c", {}}), ms::Error) << "no more frames after a failure";
  EXPECT_EQ(writer.written(), 1);
}

TEST(FrameWriter, SeveralWritersWriteEachFrameOnce) {
  std::mutex m;
  std::multiset<int> seen;
  std::atomic<int> busy{0}, most{0};
  {
    ms::FrameWriter writer(
        2, {},
        [&](const ms::WriteJob& j) {
          const int now = ++busy;
          most = std::max(most.load(), now);
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
          --busy;
          std::lock_guard<std::mutex> lock(m);
          seen.insert(j.frame);
        },
        3);
    for (int f = 0; f < 30; ++f) writer.push({f, {}, {}, {}});
    writer.finish();
    EXPECT_EQ(writer.written(), 30);
  }
  EXPECT_EQ(seen.size(), 30u);
  for (int f = 0; f < 30; ++f) EXPECT_EQ(seen.count(f), 1u) << f;
  EXPECT_GT(most.load(), 1) << "writers overlap";
  EXPECT_LE(most.load(), 3);
}

TEST(FrameWriter, DestructorWritesWhatIsQueued) {
  TempDir dir;
  {
    ms::FrameWriter writer(4);
    for (int f = 0; f < 3; ++f) writer.push({f, gray(4, 4, 0.25f), dir.path() / ("w" + std::to_string(f) + ".png"), {}});
  }
  for (int f = 0; f < 3; ++f) EXPECT_TRUE(ms::frame_is_complete(dir.path() / ("w" + std::to_string(f) + ".png"), 4, 4));
}

}  // namespace
