// A JSON value quoted in an error message is quoted briefly: a hostile value
// (hundreds of thousands of nested arrays, a megabyte string) still gives
// one short line, not the value back in full.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "run.h"

namespace ms::test {
namespace {

std::string nested_arrays(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// `lines`: a batch adds its summary ("1 of 1 job failed") after the job's line.
void expect_short_lines(const RunResult& r, const std::string& must_contain, int lines = 1) {
  EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 300);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), lines) << r.err.substr(0, 300);
  EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 300);
  EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err.substr(0, 300);
}

TEST(JsonQuotes, AJobLineOfDeepArraysIsNamedByKindNotEchoed) {
  TempDir dir;
  write_file(dir / "jobs.jsonl", nested_arrays(200000) + "\n");
  expect_short_lines(run_marchstudio({"render", "--jobs", "jobs.jsonl", "--output-dir", "o"}, dir.path()),
                     "jobs.jsonl:1: not a JSON object: an array of 1", 2);
}

TEST(JsonQuotes, AWrongTypedJobValueIsQuotedShort) {
  TempDir dir;
  write_file(dir / "jobs.jsonl", "{\"scene\": \"a.toml\", \"spp\": " +
                                     nested_arrays(1000) + "}\n");
  expect_short_lines(run_marchstudio({"render", "--jobs", "jobs.jsonl", "--output-dir", "o"}, dir.path()),
                     "'spp' must be an integer, not an array of 1", 2);
}

TEST(JsonQuotes, AShadertoyApiErrorIsQuotedShort) {
  TempDir dir;
  write_file(dir / "err.json", "{\"Error\": " + nested_arrays(200000) + "}");
  expect_short_lines(run_marchstudio({"render", "err.json", "-o", "e.png"}, dir.path()),
                     "an error from the Shadertoy API: an array of 1");
  write_file(dir / "err.json", "{\"Error\": \"Shader not found\"}");
  expect_short_lines(run_marchstudio({"render", "err.json", "-o", "e.png"}, dir.path()), "Shader not found");
  EXPECT_FALSE(std::filesystem::exists(dir / "e.png"));
}

}  // namespace
}  // namespace ms::test
