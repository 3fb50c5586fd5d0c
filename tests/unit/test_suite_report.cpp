// What `marchstudio test` writes: JUnit XML and JSON from a SuiteResult,
// the atomic text writer, and the 8-bit pixels a render is compared as.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "suite/suite_html.h"
#include "suite/suite_report.h"
#include "core/error.h"
#include "files.h"
#include "io/image_io.h"
#include "io/stored_pixels.h"
#include "io/atomic_file.h"

namespace ms {
namespace {
namespace fs = std::filesystem;


std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A suite of three cases and their results: pass, fail, could not run.
struct Fixture {
  Suite suite;
  SuiteResult result;
  Fixture() {
    suite.file = "tests/s.toml";
    suite.name = "s";
    for (const char* n : {"ok", "bad", "broken"}) {
      SuiteCase c;
      c.name = n;
      c.input = std::string("scenes/") + n + ".toml";
      c.reference = std::string("refs/") + n + ".png";
      c.checks.push_back({Metric::psnr, 40.0, {}, 1.0f / 255});
      suite.cases.push_back(c);
    }
    for (size_t i = 0; i < 3; ++i) {
      CaseResult r;
      r.spec = &suite.cases[i];
      r.width = 16;
      r.height = 9;
      CheckResult k;
      k.check = suite.cases[i].checks[0];
      k.value = i == 0 ? 55.0 : 12.5;
      k.outcome = i == 0 ? Outcome::pass : Outcome::fail;
      r.checks.push_back(k);
      r.outcome = i == 0 ? Outcome::pass : i == 1 ? Outcome::fail : Outcome::error;
      r.error_code = i == 2 ? Exit::bad_input : Exit::ok;
      r.message = i == 0 ? "psnr 55 dB >= 40 dB" : i == 1 ? "psnr 12.50 dB < 40.00 dB <&\"'>" : "x.toml:3: unknown key";
      r.seconds = 0.25;
      result.cases.push_back(r);
    }
    result.machines.emplace_back("osmesa", "llvmpipe (LLVM 15.0.6, 256 bits)");
  }
};

TEST(SuiteReport, JUnitHasOneTestcasePerCaseWithFailuresAndErrors) {
  Fixture f;
  const std::string x = suite_junit(f.suite, f.result);
  EXPECT_EQ(x.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n", 0), 0u);
  EXPECT_NE(x.find("<testsuites name=\"marchstudio test\" tests=\"3\" failures=\"1\" errors=\"1\""), std::string::npos) << x;
  EXPECT_NE(x.find("<testcase name=\"ok\" classname=\"s\" time=\"0.250\""), std::string::npos) << x;
  EXPECT_NE(x.find("<failure message=\"psnr 12.50 dB &lt; 40.00 dB &lt;&amp;&quot;&#39;&gt;\" type=\"threshold\">"),
            std::string::npos) << x;
  EXPECT_NE(x.find("<error message=\"x.toml:3: unknown key\" type=\"bad_input\">"), std::string::npos) << x;
  EXPECT_NE(x.find("<property name=\"psnr\" value=\"55\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("<property name=\"gl_renderer.osmesa\" value=\"llvmpipe (LLVM 15.0.6, 256 bits)\"/>"),
            std::string::npos);
  size_t cases = 0;
  for (size_t at = 0; (at = x.find("<testcase ", at)) != std::string::npos; ++at) ++cases;
  EXPECT_EQ(cases, 3u);
  EXPECT_EQ(x.find("<failure", x.find("name=\"ok\"")), x.find("<failure"));  // ok has none: the first is bad's
}

TEST(SuiteReport, XmlEscapeDropsWhatXmlCannotHold) {
  EXPECT_EQ(xml_escape("a<b>&\"'\x01\tz\n"), "a&lt;b&gt;&amp;&quot;&#39;\tz\n");
}

TEST(SuiteReport, JsonHasTheSchemaTheSummaryAndEveryCase) {
  Fixture f;
  const nlohmann::json j = nlohmann::json::parse(suite_json(f.suite, f.result));
  EXPECT_EQ(j.at("schema"), kTestSchema);
  EXPECT_EQ(j.at("summary").at("cases"), 3);
  EXPECT_EQ(j.at("summary").at("fail"), 1);
  EXPECT_EQ(j.at("summary").at("error"), 1);
  EXPECT_EQ(j.at("summary").at("outcome"), "error");
  ASSERT_EQ(j.at("cases").size(), 3u);
  EXPECT_EQ(j.at("cases").at(1).at("outcome"), "fail");
  EXPECT_EQ(j.at("cases").at(1).at("checks").at(0).at("value"), 12.5);
}

TEST(SuiteReport, TheHtmlPageListsFailuresFirstAndEscapes) {
  Fixture f;
  const std::string h = suite_html(f.suite, f.result);
  const size_t broken = h.find("id=\"case-broken\""), bad = h.find("id=\"case-bad\""), ok = h.find("id=\"case-ok\"");
  ASSERT_NE(ok, std::string::npos);
  EXPECT_LT(broken, bad);
  EXPECT_LT(bad, ok);
  EXPECT_NE(h.find("&lt;&amp;&quot;&#39;&gt;"), std::string::npos);
  EXPECT_EQ(h.find("http"), std::string::npos) << "the page must need no network";
}

TEST(TextIo, WritesAtomicallyAndLeavesNoTemporary) {
  test::TempDir t;
  write_text_file(t.path() / "a.xml", "hello\n");
  write_text_file(t.path() / "a.xml", "again\n");
  EXPECT_EQ(slurp(t.path() / "a.xml"), "again\n");
  EXPECT_EQ(t.entries(), std::vector<std::string>{"a.xml"});
}

TEST(TextIo, BadPathsAreBadInputAndLeaveNothing) {
  test::TempDir t;
  // A missing directory is made; one under a file cannot be.
  write_text_file(t.path() / "made/a.xml", "x", "--junit");
  EXPECT_EQ(slurp(t.path() / "made/a.xml"), "x");
  fs::remove_all(t.path() / "made");
  write_text_file(t.path() / "f", "x");
  try {
    write_text_file(t.path() / "f/sub/a.xml", "x", "--junit");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Exit::bad_input);
    EXPECT_EQ(e.info().key, "--junit");
  }
  fs::remove(t.path() / "f");
  fs::create_directory(t.path() / "d");
  EXPECT_THROW(write_text_file(t.path() / "d", "x"), Error);
  EXPECT_EQ(t.entries(), std::vector<std::string>{"d"});
}

// A render compared in memory as an 8-bit file is exactly that file read back.
TEST(StoredPixels, EqualWhatAWrittenPngReadsBackAs) {
  test::TempDir t;
  Image img;
  img.width = 7;
  img.height = 3;
  img.channels = {"R", "G", "B", "A"};
  for (int i = 0; i < 7 * 3 * 4; ++i) img.pixels.push_back(static_cast<float>(i % 13) / 12.3f - 0.05f);
  write_image(img, t.path() / "a.png");
  const Image back = read_image(t.path() / "a.png");
  const Image mem = stored_pixels(img, ImageFormat::png);
  ASSERT_EQ(mem.channels, back.channels);
  ASSERT_EQ(mem.pixels.size(), back.pixels.size());
  EXPECT_EQ(mem.pixels, back.pixels);
  EXPECT_EQ(stored_pixels(img, ImageFormat::exr).pixels, img.pixels);
}

}  // namespace
}  // namespace ms
