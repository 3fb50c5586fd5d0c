#include "render/environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>

#include "core/error.h"
#include "core/hash.h"
#include "io/cache_dir.h"
#include "io/image_io.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The real SH basis to band 2, in the order the shader evaluates it.
std::array<double, 9> sh_basis(glm::dvec3 d) {
  return {0.282095,
          0.488603 * d.y,
          0.488603 * d.z,
          0.488603 * d.x,
          1.092548 * d.x * d.y,
          1.092548 * d.y * d.z,
          0.315392 * (3.0 * d.z * d.z - 1.0),
          1.092548 * d.x * d.z,
          0.546274 * (d.x * d.x - d.y * d.y)};
}

// The cosine lobe's band weights A_l / pi (Ramamoorthi and Hanrahan): E/pi.
constexpr double kBandWeight[9] = {1.0, 2.0 / 3, 2.0 / 3, 2.0 / 3, 0.25, 0.25, 0.25, 0.25, 0.25};

// The coefficients of a cache entry; false (a miss) when it is missing, not
// a regular file or does not parse: nine lines of three finite numbers.
bool read_cache(const fs::path& f, IrradianceSh& sh) {
  std::string text;
  if (!read_cache_file(f, text, 4096)) return false;
  std::istringstream in(text);
  for (glm::vec3& c : sh)
    if (!(in >> c.x >> c.y >> c.z) || !std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
  return true;
}

// Why cached coefficients cannot be those of map `m`, or empty when they
// can: each is at most 4 pi x 1.1 times the map's brightest texel (every
// basis function is below 1.1 in magnitude on the sphere, every band weight
// <= 1), and they are not all zero unless the map is black. A planted or
// damaged entry (zeros, 1e38) is not trusted.
std::string implausible(const IrradianceSh& sh, const Image& m) {
  const int nc = std::min(m.nchannels(), 3);
  double brightest = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      for (int c = 0; c < nc; ++c) brightest = std::max(brightest, std::abs(static_cast<double>(m.at(x, y, c))));
  const double bound = brightest * 4.0 * kPi * 1.1 * (1.0 + 1e-6);
  bool all_zero = true;
  for (const glm::vec3& c : sh)
    for (int i = 0; i < 3; ++i) {
      if (std::abs(static_cast<double>(c[i])) > bound) return "a coefficient is larger than the map allows";
      all_zero = all_zero && c[i] == 0.0f;
    }
  if (all_zero && brightest > 0) return "all zero, but the map is not black";
  return {};
}

void write_cache(const fs::path& f, const IrradianceSh& sh) {
  std::ostringstream out;
  out.precision(9);
  for (const glm::vec3& c : sh) out << c.x << ' ' << c.y << ' ' << c.z << '\n';
  // A cache that cannot be written costs the next run a few milliseconds, nothing more.
  (void)write_cache_file(f, out.str());
}

}  // namespace

glm::vec3 equirect_direction(double x, double y, int w, int h) {
  const double phi = (x / w - 0.5) * 2.0 * kPi, theta = y / h * kPi;
  return glm::vec3(glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)));
}

IrradianceSh irradiance_sh(const Image& m) {
  std::array<glm::dvec3, 9> acc{};
  const int nc = m.nchannels();
  for (int y = 0; y < m.height; ++y) {
    // Each pixel's solid angle: (2 pi / w) (pi / h) sin(theta) at its centre.
    const double theta = (y + 0.5) / m.height * kPi;
    const double dw = (2.0 * kPi / m.width) * (kPi / m.height) * std::sin(theta);
    for (int x = 0; x < m.width; ++x) {
      const glm::dvec3 d(equirect_direction(x + 0.5, y + 0.5, m.width, m.height));
      const glm::dvec3 L(m.at(x, y, 0), m.at(x, y, nc > 1 ? 1 : 0), m.at(x, y, nc > 2 ? 2 : 0));
      const std::array<double, 9> b = sh_basis(d);
      for (int i = 0; i < 9; ++i) acc[i] += L * (b[i] * dw);
    }
  }
  IrradianceSh out;
  for (int i = 0; i < 9; ++i) out[i] = glm::vec3(acc[i] * kBandWeight[i]);
  return out;
}

glm::vec3 eval_irradiance(const IrradianceSh& sh, glm::vec3 n) {
  const std::array<double, 9> b = sh_basis(glm::dvec3(n));
  glm::dvec3 e(0.0);
  for (int i = 0; i < 9; ++i) e += glm::dvec3(sh[i]) * b[i];
  return glm::vec3(e);
}

fs::path irradiance_cache_path(const std::string& content_hash) {
  const fs::path dir = cache_dir();
  return dir.empty() ? fs::path() : dir / "irradiance" / (content_hash + ".txt");
}

namespace {

// The last map read, kept by path, size and modification time: the viewer
// prepares a reload on every save, and decoding an unchanged EXR again was
// almost all of envlight's reload (docs/viewer.md).
struct LoadedMap {
  fs::path file;
  std::uintmax_t size = 0;
  fs::file_time_type mtime;
  std::shared_ptr<const Image> image;
  IrradianceSh sh{};
};

}  // namespace

void attach_environment(Scene& scene, PassSource& pass, bool* from_cache) {
  if (scene.sky.environment.empty()) return;
  const fs::path& file = scene.sky.environment;
  static std::mutex m;  // render's and the viewer's threads may both load
  static LoadedMap last;
  std::error_code e1, e2;
  const std::uintmax_t size = fs::file_size(file, e1);
  const fs::file_time_type mtime = fs::last_write_time(file, e2);
  std::shared_ptr<const Image> img;
  bool cached = false;
  {
    std::lock_guard<std::mutex> lock(m);
    if (!e1 && !e2 && last.image && last.file == file && last.size == size && last.mtime == mtime) {
      img = last.image;
      scene.sky.irradiance = last.sh;
      cached = true;  // nothing computed this time
    }
  }
  if (!img) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto decoded = std::make_shared<const Image>(read_image(file));  // bad_input naming the file
    if (decoded->width < 2 || decoded->height < 1)
      fail_input("environment " + file.string() + " is " + std::to_string(decoded->width) + "x" +
                     std::to_string(decoded->height),
                 scene.file.string(), 0, "sky.environment", "an equirectangular image, twice as wide as high");
    const fs::path cache = irradiance_cache_path(Hash128().add(bytes).hex());
    cached = read_cache(cache, scene.sky.irradiance);
    if (cached)
      if (const std::string why = implausible(scene.sky.irradiance, *decoded); !why.empty()) {
        std::fprintf(stderr, "marchstudio: %s: warning: the cached irradiance of %s is not trusted (%s): computed again\n",
                     cache.string().c_str(), file.string().c_str(), why.c_str());
        cached = false;
      }
    if (!cached) {
      scene.sky.irradiance = irradiance_sh(*decoded);
      write_cache(cache, scene.sky.irradiance);
    }
    img = decoded;
    if (!e1 && !e2) {
      std::lock_guard<std::mutex> lock(m);
      last = LoadedMap{file, size, mtime, img, scene.sky.irradiance};
    }
  }
  if (from_cache) *from_cache = cached;
  GraphInput& g = pass.inputs[0];
  g.kind = InputKind::texture;
  g.image = std::move(img);
  g.file = file.string();
  g.eight_bit = false;
  g.uniform = "uEnvMap";
  g.sampler = {TexFilter::linear, TexWrap::repeat, false, false};  // row 0 (up) at v = 0, as sky.glsl reads it
}

}  // namespace ms
