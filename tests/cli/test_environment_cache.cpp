// The on-disk caches (io/cache_dir.h) are hints that are never trusted
// blindly: an irradiance entry of zeros or 1e38 is computed again with a
// warning and the image matches a clean render; the irradiance used is in
// the fingerprint; a FIFO at an irradiance or dispatch entry is a miss,
// never a hang; with neither HOME nor XDG_CACHE_HOME the cache lives only in
// a 0700 directory of ours in $TMPDIR, never through a planted link or a
// directory someone else could write.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {
namespace fs = std::filesystem;

// A 64x32 map: warm above the horizon, blue below.
void write_map(const fs::path& p, float top) {
  Image m;
  m.width = 64;
  m.height = 32;
  m.channels = {"R", "G", "B"};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) m.pixels.insert(m.pixels.end(), {y < 16 ? top : 0.0f, 0.3f, y < 16 ? 0.1f : 0.6f});
  write_image(m, p);
}

// A ball lit by the map's irradiance alone (the one light is off).
const char* kScene =
    "[scene]\nname = \"env\"\nmap = \"m.glsl\"\n"
    "[camera]\nposition = [0.0, 0.0, 0.0]\ntarget = [0.0, 0.0, 1.0]\nup = [0.0, 1.0, 0.0]\nfov = 40.0\n"
    "[render]\nwidth = 48\nheight = 48\nexposure = 1.0\n"
    "[sky]\nenvironment = \"sky.exr\"\n"
    "[[lights]]\ntype = \"directional\"\ndirection = [0.0, -1.0, 0.0]\nintensity = 0.0\n"
    "[[materials]]\nname = \"ball\"\ncolor = [1.0, 1.0, 1.0]\n";
const char* kMap = "vec2 map(vec3 p) { return vec2(sdSphere(p - vec3(0.0, 0.0, 6.0), 1.0), MAT_BALL); }\n";

struct EnvScene {
  TempDir dir;
  EnvScene() {
    write_map(dir / "sky.exr", 1.0f);
    write_file(dir / "m.glsl", kMap);
    write_file(dir / "s.toml", kScene);
  }
  fs::path cache() const { return dir / "cache"; }
  // `env`: the shell's words before the binary; a hang ends at 60 s with 124.
  RunResult render(const std::string& out, const std::vector<std::string>& extra = {}, const std::string& env = {}) {
    std::vector<std::string> args = {"render", "s.toml", "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string prefix = env.empty() ? "XDG_CACHE_HOME='" + cache().string() + "' " : env;
    return run_marchstudio(args, dir.path(), prefix + "timeout 60 ");
  }
  // The one irradiance entry under the cache.
  fs::path entry() const {
    std::vector<fs::path> found;
    for (const auto& e : fs::recursive_directory_iterator(cache()))
      if (e.path().parent_path().filename() == "irradiance") found.push_back(e.path());
    EXPECT_EQ(found.size(), 1u);
    return found.empty() ? fs::path() : found[0];
  }
};

void plant(const fs::path& entry, const std::string& value) {
  std::ofstream f(entry, std::ios::trunc);
  for (int i = 0; i < 9; ++i) f << value << ' ' << value << ' ' << value << '\n';
}

std::vector<float> coefficients(const fs::path& entry) {
  std::ifstream f(entry);
  std::vector<float> v;
  for (float x; f >> x;) v.push_back(x);
  return v;
}

TEST(EnvironmentCache, ImplausibleEntriesAreComputedAgainAndTheIrradianceIsInTheFingerprint) {
  EnvScene s;
  RunResult r = s.render("clean.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image clean = read_image(s.dir / "clean.exr");
  const std::string fingerprint = read_image_info(s.dir / "clean.exr").fingerprint;
  const fs::path entry = s.entry();
  const std::vector<float> good = coefficients(entry);
  ASSERT_EQ(good.size(), 27u);
  for (const std::string bad : {"0", "1e38", "-3e30"}) {
    plant(entry, bad);
    r = s.render("bad.exr");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: the cached irradiance of sky.exr is not trusted"), std::string::npos)
        << bad << ": " << r.err;
    EXPECT_TRUE(read_image(s.dir / "bad.exr").pixels == clean.pixels) << bad << " was used";
    EXPECT_EQ(read_image_info(s.dir / "bad.exr").fingerprint, fingerprint) << bad;
    EXPECT_EQ(coefficients(entry), good) << "the entry is rewritten with what was computed";
  }
  // A plausible entry is used (the cache works), and what it lit the image
  // with changes the fingerprint.
  {
    std::ofstream f(entry, std::ios::trunc);
    for (size_t i = 0; i < good.size(); i += 3)
      f << good[i] * 0.1f << ' ' << good[i + 1] * 0.1f << ' ' << good[i + 2] * 0.1f << '\n';
  }
  r = s.render("dim.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("not trusted"), std::string::npos) << r.err;
  EXPECT_LT(read_image(s.dir / "dim.exr").at(24, 22, 0), clean.at(24, 22, 0) * 0.5f) << "the cache was not read";
  EXPECT_NE(read_image_info(s.dir / "dim.exr").fingerprint, fingerprint);
  // Another environment: another fingerprint.
  write_map(s.dir / "sky.exr", 2.0f);
  r = s.render("other.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_image_info(s.dir / "other.exr").fingerprint, fingerprint);
}

TEST(EnvironmentCache, AFifoAtAnEntryIsAMissNotAHang) {
  EnvScene s;
  RunResult r = s.render("clean.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image clean = read_image(s.dir / "clean.exr");
  const fs::path entry = s.entry();
  fs::remove(entry);
  ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
  r = s.render("fifo.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(read_image(s.dir / "fifo.exr").pixels == clean.pixels);
  EXPECT_TRUE(fs::is_fifo(entry)) << "a FIFO is neither written through nor replaced";

  // The dispatch choice: a FIFO there, and --dispatch auto probes and goes on.
  const fs::path dispatch = s.cache() / "marchstudio" / "dispatch";
  ASSERT_EQ(::mkfifo(dispatch.c_str(), 0600), 0);
  r = s.render("auto.png", {"--dispatch", "auto", "-v"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("dispatch auto: probe:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not cached: "), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_fifo(dispatch));
}

TEST(EnvironmentCache, WithoutHomeTheCacheIsAPrivateTemporaryDirectoryOrNone) {
  EnvScene s;
  const fs::path tmp = s.dir / "tmp", victim = s.dir / "victim";
  fs::create_directories(tmp);
  fs::create_directories(victim);
  const fs::path ours = tmp / ("marchstudio-" + std::to_string(::geteuid()));
  const std::string env = "env -u HOME -u XDG_CACHE_HOME TMPDIR='" + tmp.string() + "' ";

  // Someone else's link at the name: not followed, no cache, the render fine.
  fs::create_directory_symlink(victim, ours);
  RunResult r = s.render("a.exr", {}, env);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_empty(victim)) << "the cache was written through a planted link";
  EXPECT_FALSE(fs::exists(s.dir / "irradiance")) << "no cache is no cache, not one in the working directory";
  fs::remove(ours);

  // A directory others may write (or not ours): not used.
  fs::create_directory(ours);
  fs::permissions(ours, fs::perms::owner_all | fs::perms::group_all | fs::perms::others_all);
  r = s.render("b.exr", {}, env);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_empty(ours)) << "a directory others can write was used as the cache";
  fs::remove(ours);

  // None there: made 0700, and the irradiance kept in it.
  r = s.render("c.exr", {}, env);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::lstat(ours.c_str(), &st), 0);
  EXPECT_TRUE(S_ISDIR(st.st_mode));
  EXPECT_EQ(st.st_mode & 07777, 0700u);
  EXPECT_TRUE(fs::exists(ours / "irradiance")) << "the private directory is the cache";
  EXPECT_TRUE(read_image(s.dir / "c.exr").pixels == read_image(s.dir / "a.exr").pixels);
}

}  // namespace
}  // namespace ms::test
