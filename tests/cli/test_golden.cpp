// The golden suite. Every scene in scenes/ (globbed when this binary runs),
// rendered on EGL and on OSMesa, matches tests/golden/<scene>.png within
// tests/golden/tolerances.toml, checked by `marchstudio compare` as a user's
// CI would; and renders twice bit-identically on each backend.
// A failing comparison leaves the render and a diff heat map in
// ./golden-failures/ (the ctest working directory) for a person to look at.
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

const std::vector<std::string> kBackends = {"egl", "osmesa"};

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(source_dir() / "scenes"))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path golden_dir() { return source_dir() / "tests/golden"; }
fs::path golden_of(const std::string& scene) { return golden_dir() / (scene + ".png"); }

struct Tolerance {
  double psnr_min = 0.0;
  double max_abs_max = 0.0;
};

// [<scene>.<backend>] psnr_min, max_abs_max; nullopt when absent.
std::optional<Tolerance> tolerance_for(const std::string& scene, const std::string& backend) {
  static const toml::table table = toml::parse_file((golden_dir() / "tolerances.toml").string());
  const auto psnr = table[scene][backend]["psnr_min"].value<double>();
  const auto max = table[scene][backend]["max_abs_max"].value<double>();
  if (!psnr || !max) return std::nullopt;
  return Tolerance{*psnr, *max};
}

std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Goldens are llvmpipe references: on a machine with a GPU, glvnd would give
// EGL to its driver. Pin Mesa, and software rendering within Mesa, for the
// renders of this file only (tools/update-goldens.sh does the same).
class PinLlvmpipe {
 public:
  PinLlvmpipe() {
    set("LIBGL_ALWAYS_SOFTWARE", "1");
    const char* mesa = "/usr/share/glvnd/egl_vendor.d/50_mesa.json";
    if (fs::exists(mesa)) set("__EGL_VENDOR_LIBRARY_FILENAMES", mesa);
  }
  ~PinLlvmpipe() {
    for (const auto& [name, old] : saved_)
      old ? ::setenv(name.c_str(), old->c_str(), 1) : ::unsetenv(name.c_str());
  }

 private:
  void set(const std::string& name, const std::string& value) {
    const char* old = std::getenv(name.c_str());
    saved_.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
    ::setenv(name.c_str(), value.c_str(), 1);
  }
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

class Golden : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  std::string scene = std::get<0>(GetParam());
  std::string backend = std::get<1>(GetParam());
  TempDir dir;
  PinLlvmpipe pin;

  // Renders the scene at the golden's size on this backend; empty on failure.
  fs::path render(const std::string& name) {
    const fs::path golden = golden_of(scene);
    if (!fs::exists(golden)) {
      ADD_FAILURE() << "no golden " << golden << ": run tools/update-goldens.sh, review, commit";
      return {};
    }
    const Image g = read_image(golden);
    const fs::path out = dir / name;
    RunResult r = run_marchstudio({"render", (source_dir() / "scenes" / (scene + ".toml")).string(), "-o",
                                   out.string(), "--size", std::to_string(g.width) + "x" + std::to_string(g.height),
                                   "--backend", backend, "-v"});
    if (r.exit_code != 0) {
      ADD_FAILURE() << "render failed (" << r.exit_code << "): " << r.err;
      return {};
    }
    if (r.err.find("llvmpipe") == std::string::npos) {
      ADD_FAILURE() << "goldens are llvmpipe references, but this render used: " << r.err;
      return {};
    }
    return out;
  }

  // compare GOLDEN OUT --metric M --threshold T must exit 0; on failure keep
  // the render and the heat map.
  void expect_within(const fs::path& out, const std::string& metric, double threshold) {
    const fs::path diff = dir / ("diff-" + metric + ".png");
    RunResult r = run_marchstudio({"compare", golden_of(scene).string(), out.string(), "--metric", metric,
                                   "--threshold", fmt(threshold), "--diff", diff.string()});
    if (r.exit_code == 0) return;
    const fs::path keep = fs::current_path() / "golden-failures";
    std::error_code ec;
    fs::create_directories(keep, ec);
    const std::string stem = scene + "." + backend;
    fs::copy_file(out, keep / (stem + ".png"), fs::copy_options::overwrite_existing, ec);
    fs::copy_file(diff, keep / (stem + ".diff.png"), fs::copy_options::overwrite_existing, ec);
    ADD_FAILURE() << scene << " on " << backend << ": " << metric << " outside tolerance " << threshold
                  << " (exit " << r.exit_code << "); render and heat map in " << keep.string() << "\n"
                  << r.out << r.err;
  }
};

TEST_P(Golden, MatchesTheGoldenWithinTolerance) {
  const std::optional<Tolerance> tol = tolerance_for(scene, backend);
  ASSERT_TRUE(tol) << "no [" << scene << "." << backend << "] psnr_min/max_abs_max in tests/golden/tolerances.toml";
  const fs::path out = render("render.png");
  if (out.empty()) return;
  expect_within(out, "psnr", tol->psnr_min);
  expect_within(out, "max", tol->max_abs_max);
}

// Bit-identical pixel data: float EXR, so not even a rounding to 8 bits hides a change.
TEST_P(Golden, RendersTwiceBitIdentically) {
  const fs::path a = render("a.exr"), b = render("b.exr");
  if (a.empty() || b.empty()) return;
  const Image ia = read_image(a), ib = read_image(b);
  ASSERT_EQ(ia.width, ib.width);
  ASSERT_EQ(ia.height, ib.height);
  ASSERT_EQ(ia.channels, ib.channels);
  ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < ia.pixels.size(); ++i)
    differing += std::memcmp(&ia.pixels[i], &ib.pixels[i], sizeof(float)) != 0;
  EXPECT_EQ(differing, 0u) << scene << " on " << backend << ": values differ between two identical renders";
}

std::string case_name(const ::testing::TestParamInfo<Golden::ParamType>& info) {
  std::string s = std::get<0>(info.param) + "_" + std::get<1>(info.param);
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden,
                         ::testing::Combine(::testing::ValuesIn(scene_names()), ::testing::ValuesIn(kBackends)),
                         case_name);

// The suite's bookkeeping, without GL: a new scene cannot slip in without a
// golden, tolerances and a gallery entry, nor a deleted one leave them behind.
TEST(GoldenSuite, EverySceneHasAGoldenTolerancesAndAGalleryEntry) {
  const std::vector<std::string> scenes = scene_names();
  ASSERT_FALSE(scenes.empty());
  const std::string gallery = read_file(source_dir() / "docs/gallery.md");
  for (const std::string& s : scenes) {
    EXPECT_TRUE(fs::exists(golden_of(s))) << s << ": run tools/update-goldens.sh";
    for (const std::string& be : kBackends) EXPECT_TRUE(tolerance_for(s, be)) << "[" << s << "." << be << "]";
    const fs::path copy = source_dir() / "docs/images/gallery" / (s + ".png");
    EXPECT_TRUE(fs::exists(copy) && read_file(copy) == read_file(golden_of(s)))
        << copy << " is not a copy of the golden: run tools/update-goldens.sh";
    EXPECT_NE(gallery.find("images/gallery/" + s + ".png"), std::string::npos) << "docs/gallery.md lacks " << s;
  }
  for (const auto& e : fs::directory_iterator(golden_dir()))
    if (e.path().extension() == ".png")
      EXPECT_TRUE(std::count(scenes.begin(), scenes.end(), e.path().stem().string()))
          << e.path() << " has no scene in scenes/";
}

}  // namespace
}  // namespace ms::test
