// io/: atomic-write temporaries are recognisable, so a resumed run can clean
// up after a killed one without touching anything else, and they fit the
// file system's name limit whatever the target's length. AtomicFile
// reports what it could not write, and input files must be regular.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "files.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/input_file.h"

namespace ms {
namespace {
namespace fs = std::filesystem;

TEST(ImageIoTemp, TempPathIsRecognisedAsItsTargets) {
  const fs::path tmp = temp_path_for("out/frame_0007.png", 4242);
  EXPECT_EQ(tmp, fs::path("out/.frame_0007.png.tmp4242"));
  EXPECT_TRUE(is_temp_of(tmp.filename().string(), "out/frame_0007.png"));
  EXPECT_FALSE(is_temp_of(tmp.filename().string(), "out/frame_0008.png"));
  // ffmpeg picks the container by the extension: kept last.
  const fs::path vid = temp_path_for("v.mp4", 7, true);
  EXPECT_EQ(vid, fs::path(".v.tmp7.mp4"));
  EXPECT_TRUE(is_temp_of(vid.filename().string(), "v.mp4"));
}

TEST(ImageIoTemp, OtherFilesAreNotTemporaries) {
  for (const char* name : {"frame_0007.png", ".frame_0007.png.tmp", ".frame_0007.png.tmpx12", "frame_0007.png.tmp12",
                           ".frame_0007.png.tmp12.bak", ".hidden", ".frame_0007.tmp12.exr"})
    EXPECT_FALSE(is_temp_of(name, "frame_0007.png")) << name;
  // The extension-last form (video temporaries, and images before 0.2) is one too.
  EXPECT_TRUE(is_temp_of(".frame_0007.tmp12.png", "frame_0007.png"));
}

TEST(ImageIoTemp, LongNamesGetTemporariesWithinTheLimit) {
  const std::size_t limit = name_limit(".");
  for (std::size_t len : {limit - 4, limit}) {
    const std::string name = std::string(len - 4, 'a') + ".png";
    const fs::path tmp = temp_path_for(name, 4194304);
    EXPECT_LE(tmp.filename().string().size(), limit) << len;
    EXPECT_TRUE(is_temp_of(tmp.filename().string(), name)) << len;
    // Two names alike in their first bytes get different temporaries.
    const std::string other = std::string(len - 5, 'a') + "b.png";
    EXPECT_NE(temp_path_for(other, 4194304), tmp);
    EXPECT_FALSE(is_temp_of(tmp.filename().string(), other));
  }
}

class AtomicFileTest : public ::testing::Test {
 protected:
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(dir), {})); }
  test::TempDir tmp_dir;
  fs::path dir = tmp_dir.path();
};

TEST_F(AtomicFileTest, TheTargetAppearsOnlyOnCommit) {
  {
    AtomicFile f(dir / "a.txt");
    ASSERT_TRUE(f.write("hello ", 6));
    ASSERT_TRUE(f.pwrite("world", 5, 6));
    EXPECT_FALSE(fs::exists(dir / "a.txt"));
    EXPECT_TRUE(fs::exists(f.temp()));
    f.commit();
  }
  std::ifstream in(dir / "a.txt");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(text, "hello world");
  EXPECT_EQ(entries(), 1u);
  { AtomicFile abandoned(dir / "b.txt"); abandoned.write("x", 1); }  // never committed
  EXPECT_EQ(entries(), 1u);
}

// A file size limit makes writes past it fail (EFBIG), as a full disk does
// (ENOSPC): the commit must throw, and neither the target nor the temporary
// may remain. Through write_image too, for every format.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);  // a write past it then fails instead of killing us
    rlimit r = old_;
    r.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
};

TEST_F(AtomicFileTest, AFailedWriteFailsTheCommitAndLeavesNothing) {
  const std::string big(5000, 'x');
  {
    FileSizeLimit limit(1000);
    AtomicFile f(dir / "c.txt");
    EXPECT_FALSE(f.write(big.data(), big.size()));
    EXPECT_TRUE(f.failed());
    try {
      f.commit();
      ADD_FAILURE() << "a short write was committed";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Exit::system);
      EXPECT_NE(std::string(e.what()).find("c.txt: cannot write the file"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(entries(), 0u);
  Image img;
  img.width = img.height = 64;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.resize(64 * 64 * 4);
  std::uint32_t state = 12345;  // noise, so no format compresses it below the limit
  for (float& v : img.pixels) v = static_cast<float>((state = state * 1664525u + 1013904223u) >> 24) / 255.0f;
  for (const char* name : {"i.png", "i.jpg", "i.tif", "i.exr"}) {
    {
      FileSizeLimit limit(1000);
      EXPECT_THROW(write_image(img, dir / name), Error) << name;
    }
    EXPECT_EQ(entries(), 0u) << name;
    write_image(img, dir / name);  // without the limit it is written
    EXPECT_EQ(entries(), 1u) << name;
    fs::remove(dir / name);
  }
}

TEST(InputFile, NonRegularFilesAreNamedForWhatTheyAre) {
  EXPECT_EQ(input_file_problem("/no/such/file"), "not found");
  EXPECT_EQ(input_file_problem("/tmp"), "is a directory, not a regular file");
  EXPECT_EQ(input_file_problem("/dev/zero"), "is a device, not a regular file");
  const test::TempDir dir;
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(input_file_problem(fifo), "is a FIFO (named pipe), not a regular file");
  try {
    read_input_file(fifo, "scene file", "scene.map");  // returns at once: no writer is waited for
    ADD_FAILURE() << "a FIFO was read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), fifo.string() + ": scene.map: scene file is a FIFO (named pipe), not a regular file");
  }
  EXPECT_THROW(read_input_file("/dev/zero", "image"), Error);
}

// Every format reads back what was written, with its metadata: TIFF once
// came out with a broken directory through the checked-write proxy, since
// libtiff rereads what it wrote.
TEST_F(AtomicFileTest, EveryFormatReadsBackWithItsFingerprint) {
  Image img;
  img.width = 24;
  img.height = 16;
  img.channels = {"R", "G", "B", "A"};
  img.pixels.resize(24 * 16 * 4);
  for (int y = 0; y < 16; ++y)  // smooth ramps, which JPEG keeps well too
    for (int x = 0; x < 24; ++x) {
      float* p = &img.pixels[(y * 24 + x) * 4];
      p[0] = x / 23.0f;
      p[1] = y / 15.0f;
      p[2] = 0.5f;
      p[3] = 1.0f;
    }
  for (const char* name : {"r.png", "r.jpg", "r.tif", "r.exr"}) {
    ImageMetadata meta{{"ImageDescription", "a test"}};
    add_fingerprint(meta, "0123456789abcdef0123456789abcdef");
    write_image(img, dir / name, meta);
    const ImageInfo info = read_image_info(dir / name);
    EXPECT_EQ(info.width, 24) << name;
    EXPECT_EQ(info.height, 16) << name;
    EXPECT_EQ(info.fingerprint, "0123456789abcdef0123456789abcdef") << name;
    const Image back = read_image(dir / name);
    ASSERT_EQ(back.width, 24) << name;
    ASSERT_GE(back.nchannels(), 3) << name;
    double err = 0.0;
    for (int p = 0; p < 24 * 16; ++p)
      for (int c = 0; c < 3; ++c)
        err = std::max(err, static_cast<double>(std::abs(back.pixels[p * back.nchannels() + c] - img.pixels[p * 4 + c])));
    // 8-bit: half a level; JPEG at quality 95 with 4:2:0 chroma on these ramps: up to 8 levels measured.
    EXPECT_LE(err, std::string(name) == "r.jpg" ? 12.0 / 255 : std::string(name) == "r.exr" ? 0.0 : 0.5 / 255 + 1e-6)
        << name;
  }
}

}  // namespace
}  // namespace ms
