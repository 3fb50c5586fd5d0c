// `marchstudio test --report DIR` checked in a real browser: headless
// Chromium (Debian's package, tools/install-deps.sh) loads DIR/index.html
// from disk, with no network, and its DOM must hold one row per case,
// failures first, and every image loaded (the page marks each image
// data-loaded="yes" or "no" once the browser has decoded it or given up).
// Without Chromium the test skips, saying so; in CI (CI set) it fails, as
// CI installs it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <unistd.h>

#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// The first of Debian's and other distributions' names found on PATH.
std::string find_chromium() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin";
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    size_t start = 0;
    while (start <= dirs.size()) {
      const size_t end = std::min(dirs.find(':', start), dirs.size());
      const fs::path p = fs::path(dirs.substr(start, end - start)) / name;
      if (::access(p.c_str(), X_OK) == 0) return p.string();
      start = end + 1;
    }
  }
  return {};
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = 0; (at = text.find(what, at)) != std::string::npos; at += what.size()) ++n;
  return n;
}

TEST(TestReport, AHeadlessBrowserShowsEveryCaseAndImageFailuresFirst) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    const char* ci = std::getenv("CI");
    if (ci && *ci) FAIL() << "CI is set but there is no chromium on PATH: tools/install-deps.sh installs it";
    GTEST_SKIP() << "no chromium on PATH (Debian: apt-get install chromium, as tools/install-deps.sh does): "
                    "the HTML report is not checked in a browser";
  }
  TempDir dir;
  const std::string seed = (source_dir() / "scenes/seed.toml").string();
  const std::string golden = (source_dir() / "tests/golden/seed.png").string();
  write_file(dir / "suite.toml", "[[case]]\nname = \"same\"\nscene = \"" + seed + "\"\nreference = \"" + golden +
                                     "\"\nthreshold = 60\n[[case]]\nname = \"moved\"\nscene = \"" + seed +
                                     "\"\nreference = \"" + golden + "\"\ntime = 0.05\nthreshold = 60\n");
  const fs::path report = dir / "report";
  const RunResult r = run_marchstudio({"test", (dir / "suite.toml").string(), "--report", report.string()});
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  for (const char* f : {"index.html", "moved.reference.png", "moved.result.png", "moved.diff.png", "same.result.png"})
    EXPECT_TRUE(fs::exists(report / f)) << f;

  // The browser reads the page straight from disk; nothing else may load.
  const fs::path profile = dir / "profile", dom = dir / "dom.html", log = dir / "chromium.log";
  const std::string cmd = quote(chromium) +
                          " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --user-data-dir=" + quote(profile.string()) +
                          " --virtual-time-budget=10000 --dump-dom " + quote("file://" + (report / "index.html").string()) +
                          " >" + quote(dom.string()) + " 2>" + quote(log.string()) + " </dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << read_file(log);
  const std::string html = read_file(dom);
  ASSERT_NE(html.find("<table id=\"cases\">"), std::string::npos) << "no report in the DOM:\n" << html << read_file(log);

  // Two rows, the failing one first.
  EXPECT_EQ(count(html, "<tr class=\"case "), 2u) << html;
  const size_t moved = html.find("id=\"case-moved\""), same = html.find("id=\"case-same\"");
  ASSERT_NE(moved, std::string::npos);
  ASSERT_NE(same, std::string::npos);
  EXPECT_LT(moved, same);
  EXPECT_NE(html.find("data-outcome=\"fail\"", html.rfind("<tr", moved)), std::string::npos);
  EXPECT_NE(html.find("<p class=\"summary\" id=\"summary\" data-outcome=\"fail\">"), std::string::npos) << html;

  // Three images a case, each decoded by the browser.
  EXPECT_EQ(count(html, "<img "), 6u) << html;
  static const std::regex loaded("<img [^>]*data-loaded=\"yes\""), broken("<img [^>]*data-loaded=\"no\"");
  auto matches = [&](const std::regex& re) {
    return std::distance(std::sregex_iterator(html.begin(), html.end(), re), std::sregex_iterator());
  };
  EXPECT_EQ(matches(loaded), 6) << html;
  EXPECT_EQ(matches(broken), 0) << html;
  static const std::regex src("<img src=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator(); ++it)
    EXPECT_TRUE(fs::exists(report / (*it)[1].str())) << (*it)[1].str();
  // The metrics are in the row.
  EXPECT_NE(html.find("psnr "), std::string::npos);
  EXPECT_NE(html.find("&lt; 60.00 dB"), std::string::npos) << html;
}

}  // namespace
}  // namespace ms::test
