// `render --jobs FILE` reads its file a line at a time (cli/job_list.h):
// memory holds one line, not every job, and a line over 1 MiB is skipped
// without being kept. Each case runs under an address-space cap that the
// old read-everything-first loader could not stay within.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <string>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// 700 MB: no job is valid, so no GL context is made; the 256 MiB compile
// stack (core/big_stack.h) and malloc's thread arena are most of it.
const std::string kLimit = address_space_limit(700000);

int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = 0; (at = text.find(needle, at)) != std::string::npos; at += needle.size()) ++n;
  return n;
}

TEST(BatchStream, ALineOfAGigabyteFailsAloneWithoutBeingKept) {
  TempDir dir;
  // Line 2 is 1 GiB of zero bytes (a sparse file: nothing on disk), then line 3.
  write_file(dir / "jobs.jsonl", "{\"scene\": 1}\n");
  const int fd = ::open((dir / "jobs.jsonl").c_str(), O_WRONLY);
  ASSERT_GE(fd, 0);
  const off_t big = off_t{1} << 30;
  ASSERT_EQ(::ftruncate(fd, 13 + big), 0);
  ASSERT_EQ(::lseek(fd, 0, SEEK_END), 13 + big);
  const std::string tail = "\n{\"scene\": \"missing.toml\"}\n";
  ASSERT_EQ(::write(fd, tail.data(), tail.size()), static_cast<ssize_t>(tail.size()));
  ::close(fd);
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl"}, dir.path(), kLimit);
  fs::remove(dir / "jobs.jsonl");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:1: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:2: the line is over 1 MiB: no job is that long\n"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:3: "), std::string::npos) << r.err;  // read on past it
  EXPECT_NE(r.err.find("marchstudio: 3 of 3 jobs failed\n"), std::string::npos) << r.err;
}

TEST(BatchStream, TwoHundredThousandLinesAreNotAllKept) {
  TempDir dir;
  std::string jobs;  // kept whole, as they were, they needed about 2 KB a line
  for (int i = 0; i < 200000; ++i) jobs += "{\"scene\": " + std::to_string(i) + "}\n";
  write_file(dir / "jobs.jsonl", jobs);
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl"}, dir.path(), kLimit);
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 2000);
  EXPECT_EQ(count(r.err, "must be a string"), 200000);
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:200000: 'scene' must be a string, not 199999\n"), std::string::npos);
  EXPECT_NE(r.err.find("marchstudio: 200000 of 200000 jobs failed\n"), std::string::npos);
}

TEST(BatchStream, ASecondJobWritingTheSameFileFailsAloneAfterTheFirstIsWritten) {
  TempDir dir;
  const std::string seed = (source_dir() / "scenes" / "seed.toml").string();
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + seed + "\", \"output\": \"a.png\"}\n"
                                 "{\"scene\": \"" + seed + "\", \"output\": \"./a.png\", \"time\": 1}\n"
                                 "{\"scene\": \"" + seed + "\", \"output\": \"b.png\"}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "16x9"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("marchstudio: jobs.jsonl:2: 'jobs.jsonl:1' already writes "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("marchstudio: 1 of 3 jobs failed\n"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  EXPECT_TRUE(fs::exists(dir / "b.png"));
}

}  // namespace
}  // namespace ms::test
