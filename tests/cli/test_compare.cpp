// `marchstudio compare` through the real binary: exit codes 0/1/2, the
// threshold boundary per metric, one-line errors naming the file, and the
// --diff image (right size, atomic, only when asked).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

constexpr int W = 32, H = 16;

Image gradient() {
  Image img;
  img.width = W;
  img.height = H;
  img.channels = {"R", "G", "B"};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      img.pixels.push_back(static_cast<float>(x * 8) / 255.0f);
      img.pixels.push_back(static_cast<float>(y * 16) / 255.0f);
      img.pixels.push_back(128.0f / 255.0f);
    }
  return img;
}

// A value from compare --json output, as printed (doubles round-trip).
std::string json_field(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": ([^,\\n]+)");
  std::smatch m;
  if (!std::regex_search(json, m, re)) return "";
  return m[1];
}

std::string fmt17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

struct Compare : ::testing::Test {
  TempDir dir;
  std::string a, b, same;  // a reference, b with one value changed by 10 levels, same = copy of a

  void SetUp() override {
    a = (dir / "a.png").string();
    b = (dir / "b.png").string();
    same = (dir / "same.png").string();
    Image img = gradient();
    write_image(img, a);
    write_image(img, same);
    img.pixels[(5 * W + 7) * 3 + 1] = 90.0f / 255.0f;  // pixel (7,5), green: 80 -> 90 levels
    write_image(img, b);
  }

  RunResult compare(std::vector<std::string> extra, const std::string& x, const std::string& y) {
    std::vector<std::string> args = {"compare", x, y};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_marchstudio(args, dir.path());
  }
  RunResult compare(std::vector<std::string> extra = {}) { return compare(std::move(extra), a, b); }

  // Exit 2, nothing on stdout, one line on stderr naming `name`.
  void expect_bad_input(const RunResult& r, const std::string& name) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_EQ(r.err.rfind("marchstudio: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  }
};

TEST_F(Compare, OnePixelChangeFailsTightAndPassesLooseThresholds) {
  // One green value of 512 RGB pixels off by 10/255: PSNR = 20 log10(25.5) + 10 log10(1536) = 59.99 dB.
  EXPECT_EQ(compare().exit_code, 1);  // default: exact match
  EXPECT_EQ(compare({"--threshold", "65"}).exit_code, 1);
  EXPECT_EQ(compare({"--threshold", "55"}).exit_code, 0);
  EXPECT_EQ(compare({"--metric", "max", "--threshold", "0.03"}).exit_code, 1);
  EXPECT_EQ(compare({"--metric", "max", "--threshold", "0.05"}).exit_code, 0);
  EXPECT_EQ(compare({"--metric", "mae", "--threshold", "1e-5"}).exit_code, 1);
  EXPECT_EQ(compare({"--metric", "mae", "--threshold", "1e-4"}).exit_code, 0);
  EXPECT_EQ(compare({"--metric", "fraction", "--threshold", "0.001"}).exit_code, 1);  // 1/512 = 0.00195
  EXPECT_EQ(compare({"--metric", "fraction", "--threshold", "0.002"}).exit_code, 0);
  // A 10-level change is under a pixel threshold of 12 levels: no pixel "differs".
  EXPECT_EQ(compare({"--metric", "fraction", "--threshold", "0", "--pixel-threshold", "0.047"}).exit_code, 0);
}

TEST_F(Compare, ReportNamesEveryMetricAndWhereTheMaxIs) {
  RunResult r = compare({"--threshold", "65"});
  EXPECT_EQ(r.exit_code, 1);
  for (const char* s : {"psnr      59.99 dB", "mae ", "max ", "x=7 y=5 G", "fraction", "1 of 512 pixels", "FAIL"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << " in:\n" << r.out;
  // Over the threshold: one line on stderr too, for CI logs.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("below the threshold"), std::string::npos) << r.err;
}

TEST_F(Compare, IdenticalImagesPrintInfinitePsnrAndPass) {
  RunResult r = compare({}, a, same);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("psnr      inf dB (identical)"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
  RunResult j = compare({"--json"}, a, same);
  EXPECT_EQ(j.exit_code, 0);
  EXPECT_EQ(json_field(j.out, "psnr"), "null");  // JSON has no inf
  EXPECT_EQ(json_field(j.out, "identical"), "true");
  EXPECT_EQ(std::stod(json_field(j.out, "max")), 0.0);
  EXPECT_EQ(json_field(j.out, "pass"), "true");
}

TEST_F(Compare, EachMetricPassesAtItsBoundaryAndFailsJustInside) {
  RunResult j = compare({"--json", "--threshold", "0"});
  ASSERT_EQ(j.exit_code, 0) << j.err;
  for (const char* metric : {"psnr", "mae", "max", "fraction", "flip"}) {
    const std::string v = json_field(j.out, metric);
    ASSERT_FALSE(v.empty()) << metric << " in " << j.out;
    EXPECT_EQ(compare({"--metric", metric, "--threshold", v}).exit_code, 0) << metric << " at " << v;
    const double d = std::stod(v);
    const double stricter = std::string(metric) == "psnr" ? d + 1e-9 : d * (1.0 - 1e-9);
    EXPECT_EQ(compare({"--metric", metric, "--threshold", fmt17(stricter)}).exit_code, 1) << metric;
  }
}

TEST_F(Compare, UnknownMetricAndBadThresholdsAreBadInput) {
  expect_bad_input(compare({"--metric", "ssim"}), "--metric");
  expect_bad_input(compare({"--metric", "max", "--threshold", "-1"}), "--threshold");
  expect_bad_input(compare({"--threshold", "nan"}), "--threshold");
  expect_bad_input(compare({"--pixel-threshold", "-0.1"}), "--pixel-threshold");
}

TEST_F(Compare, MissingFileIsBadInputNamingIt) {
  expect_bad_input(compare({}, a, "missing.png"), "missing.png");
  expect_bad_input(compare({}, "gone.png", b), "gone.png");
}

TEST_F(Compare, CorruptFileIsBadInputNamingIt) {
  write_file(dir / "corrupt.png", "this is not a PNG file\n");
  expect_bad_input(compare({}, a, "corrupt.png"), "corrupt.png");
}

TEST_F(Compare, TruncatedPngIsBadInputNamingIt) {
  const std::string bytes = read_file(a);
  ASSERT_GT(bytes.size(), 100u);
  write_file(dir / "header-only.png", bytes.substr(0, 40));       // cut inside IHDR
  write_file(dir / "half.png", bytes.substr(0, bytes.size() / 2));  // cut inside IDAT
  expect_bad_input(compare({}, a, "header-only.png"), "header-only.png");
  expect_bad_input(compare({}, a, "half.png"), "half.png");
}

TEST_F(Compare, DifferentSizesAreBadInputNamingBothFiles) {
  Image small = gradient();
  small.height = H / 2;
  small.pixels.resize(static_cast<size_t>(W) * (H / 2) * 3);
  write_image(small, dir / "small.png");
  RunResult r = compare({}, a, "small.png");
  expect_bad_input(r, "small.png");
  EXPECT_NE(r.err.find("32x8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a.png (32x16)"), std::string::npos) << r.err;
}

TEST_F(Compare, DifferentChannelCountsAreBadInput) {
  Image rgba = gradient();
  rgba.channels = {"R", "G", "B", "A"};
  rgba.pixels.clear();
  for (int i = 0; i < W * H; ++i) rgba.pixels.insert(rgba.pixels.end(), {0.1f, 0.2f, 0.3f, 1.0f});
  write_image(rgba, dir / "rgba.exr");
  expect_bad_input(compare({}, a, "rgba.exr"), "rgba.exr");
}

TEST_F(Compare, NanFailsWhateverTheThreshold) {
  Image img = gradient();
  write_image(img, dir / "ok.exr");
  img.pixels[3] = std::nanf("");
  write_image(img, dir / "nan.exr");
  RunResult r = compare({"--metric", "max", "--threshold", "1000"}, "ok.exr", "nan.exr");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("nonfinite A 0, B 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("NaN/Inf"), std::string::npos) << r.err;
}

TEST_F(Compare, DiffIsWrittenOnlyWhenAskedAtTheInputSize) {
  auto sorted_entries = [&] {
    auto e = dir.entries();
    std::sort(e.begin(), e.end());
    return e;
  };
  const auto before = sorted_entries();
  EXPECT_EQ(compare({"--threshold", "55"}).exit_code, 0);
  EXPECT_EQ(sorted_entries(), before) << "compare without --diff wrote a file";

  // Written on failure too (that is when one looks at it), with no temporary left.
  RunResult r = compare({"--diff", "d.png"});
  EXPECT_EQ(r.exit_code, 1);
  auto after = before;
  after.push_back("d.png");
  std::sort(after.begin(), after.end());
  EXPECT_EQ(sorted_entries(), after);
  const Image d = read_image(dir / "d.png");
  EXPECT_EQ(d.width, W);
  EXPECT_EQ(d.height, H);
  EXPECT_EQ(d.nchannels(), 3);
  // The changed pixel is the hottest one.
  auto heat = [&](int x, int y) { return d.at(x, y, 0) + d.at(x, y, 1) + d.at(x, y, 2); };
  EXPECT_GT(heat(7, 5), 2.0f);
  EXPECT_LT(heat(0, 0), 0.1f);

  // Bad input leaves an existing diff untouched.
  const std::string old = read_file(dir / "d.png");
  expect_bad_input(compare({"--diff", "d.png"}, a, "missing.png"), "missing.png");
  EXPECT_EQ(read_file(dir / "d.png"), old);
  EXPECT_EQ(sorted_entries(), after);
}

TEST_F(Compare, DiffNeverOverwritesAnInput) {
  const std::string before = read_file(a);
  expect_bad_input(compare({"--diff", "a.png"}), "--diff");
  EXPECT_EQ(read_file(a), before);
}

TEST_F(Compare, DiffIntoADirectoryThatCannotBeMadeFailsBeforeReading) {
  write_file(dir / "afile", "x");
  RunResult r = compare({"--diff", (dir / "afile/sub/d.png").string()}, a, "missing.png");
  expect_bad_input(r, "--diff");  // the output path is checked first
  EXPECT_NE(r.err.find("afile/sub"), std::string::npos) << r.err;
}

// --warn and --exit-codes idiff: OpenImageIO idiff's codes (0 pass, 1 warn,
// 2 fail, 4 could not run) for scripts written around it. PSNR of b is 59.99 dB.
TEST_F(Compare, IdiffExitCodesAndAWarnLevel) {
  const std::vector<std::string> idiff = {"--exit-codes", "idiff"};
  auto with = [&](std::vector<std::string> x) {
    x.insert(x.end(), idiff.begin(), idiff.end());
    return compare(x);
  };
  EXPECT_EQ(with({"--threshold", "55"}).exit_code, 0);
  const RunResult warn = with({"--threshold", "55", "--warn", "62"});
  EXPECT_EQ(warn.exit_code, 1) << warn.err;
  EXPECT_NE(warn.out.find("WARN: psnr 59.99 dB >= 55.00 dB, past the warn level 62.00 dB"), std::string::npos)
      << warn.out;
  EXPECT_NE(warn.err.find("warning"), std::string::npos) << warn.err;
  EXPECT_EQ(with({"--threshold", "65"}).exit_code, 2);
  EXPECT_EQ(with({"--metric", "max", "--threshold", "0.05", "--warn", "0.03"}).exit_code, 1);
  EXPECT_EQ(with({"--metric", "max", "--threshold", "0.05", "--warn", "0.04"}).exit_code, 0);
  // Could not run: a missing file, bad flags after parsing, a warn level past the threshold.
  const RunResult missing = compare({"--exit-codes", "idiff"}, a, (dir / "nope.png").string());
  EXPECT_EQ(missing.exit_code, 4);
  EXPECT_NE(missing.err.find("nope.png"), std::string::npos) << missing.err;
  EXPECT_EQ(with({"--threshold", "55", "--warn", "50"}).exit_code, 4);
  // The default codes: a warning still passes, a bad warn level is bad input.
  const RunResult plain = compare({"--threshold", "55", "--warn", "62"});
  EXPECT_EQ(plain.exit_code, 0);
  EXPECT_NE(plain.out.find("WARN"), std::string::npos);
  expect_bad_input(compare({"--threshold", "55", "--warn", "50"}), "--warn");
  expect_bad_input(compare({"--exit-codes", "oiio"}), "--exit-codes");
  const RunResult j = compare({"--threshold", "55", "--warn", "62", "--json"});
  EXPECT_EQ(json_field(j.out, "outcome"), "\"warn\"");
  EXPECT_EQ(json_field(j.out, "warn"), "62.0");
  EXPECT_EQ(json_field(j.out, "pass"), "true");
}

}  // namespace
}  // namespace ms::test
