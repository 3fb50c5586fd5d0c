#include "io/cube_faces.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/memory_budget.h"
#include "io/image_io.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Any channel layout as RGBA (grey, grey + alpha, RGB, RGBA), top row first.
Image to_rgba(const Image& img) {
  const int nc = img.nchannels();
  Image out;
  out.width = img.width;
  out.height = img.height;
  out.channels = {"R", "G", "B", "A"};
  out.pixels.resize(static_cast<size_t>(img.width) * img.height * 4);
  for (size_t p = 0; p < static_cast<size_t>(img.width) * img.height; ++p) {
    const float* s = img.pixels.data() + p * nc;
    float* d = out.pixels.data() + p * 4;
    d[0] = s[0];
    d[1] = nc > 2 ? s[1] : s[0];
    d[2] = nc > 2 ? s[2] : s[0];
    d[3] = nc >= 4 ? s[3] : nc == 2 ? s[1] : 1.0f;
  }
  return out;
}

// Six RGBA float faces of `size`, checked before any is made.
void check_cube_memory(int size, const std::string& file) {
  check_input_memory(6.0 * 16.0 * size * size, "a cubemap of six " + std::to_string(size) + "x" + std::to_string(size) +
                                                    " float faces",
                     file, "scale the image down");
}

}  // namespace

CubeFaces read_cube_faces(const std::array<fs::path, 6>& files) {
  static const char* names[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  CubeFaces c;
  c.eight_bit = !is_float_image_name(files[0]);
  for (int i = 0; i < 6; ++i) {
    const Image img = read_image(files[i], AlphaMode::straight);  // the file's bytes; missing or unreadable: bad_input
    const std::string face = std::string("cubemap face ") + std::to_string(i) + " (" + names[i] + ")";
    if (img.width != img.height)
      fail_input(face + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) + ", not square",
                 files[i].string(), 0, {}, "each of a cubemap's six faces is a square image");
    if (i > 0 && img.width != c.size)
      fail_input(face + " is " + std::to_string(img.width) + "x" + std::to_string(img.height) + ", but face 0 (" +
                     files[0].string() + ") is " + std::to_string(c.size) + "x" + std::to_string(c.size),
                 files[i].string(), 0, {}, "all six faces of a cubemap have one size");
    if (i == 0) check_cube_memory(img.width, files[0].string());
    c.size = img.width;
    c.faces[i] = to_rgba(img);
  }
  return c;
}

void cube_face_direction(int face, float s, float t, float dir[3]) {
  // (sc, tc) in [-1, 1]; GL picks face f for a direction whose major axis is
  // f's and maps it to s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
  const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
  float x = 0, y = 0, z = 0;
  switch (face) {
    case 0: x = 1; y = -tc; z = -sc; break;   // +X: sc = -z, tc = -y
    case 1: x = -1; y = -tc; z = sc; break;   // -X: sc = +z, tc = -y
    case 2: x = sc; y = 1; z = tc; break;     // +Y: sc = +x, tc = +z
    case 3: x = sc; y = -1; z = -tc; break;   // -Y: sc = +x, tc = -z
    case 4: x = sc; y = -tc; z = 1; break;    // +Z: sc = +x, tc = -y
    default: x = -sc; y = -tc; z = -1; break; // -Z: sc = -x, tc = -y
  }
  const float n = std::sqrt(x * x + y * y + z * z);
  dir[0] = x / n;
  dir[1] = y / n;
  dir[2] = z / n;
}

CubeFaces equirect_to_cube(const Image& equirect, int size, const std::string& file) {
  const int w = equirect.width, h = equirect.height;
  if (w < 1 || h < 1) fail_input("an empty equirectangular image", file);
  CubeFaces c;
  c.eight_bit = false;
  c.size = size > 0 ? size : std::max(1, w / 4);
  check_cube_memory(c.size, file);  // a 60000x1 strip would be six 15000^2 faces
  const Image src = to_rgba(equirect);
  const double pi = 3.14159265358979323846;
  const auto texel = [&](int x, int y, int k) {
    x = ((x % w) + w) % w;             // longitude wraps
    y = std::clamp(y, 0, h - 1);       // latitude stops at the poles
    return src.pixels[(static_cast<size_t>(y) * w + x) * 4 + k];
  };
  for (int f = 0; f < 6; ++f) {
    Image& face = c.faces[f];
    face.width = face.height = c.size;
    face.channels = {"R", "G", "B", "A"};
    face.pixels.resize(static_cast<size_t>(c.size) * c.size * 4);
    for (int j = 0; j < c.size; ++j)
      for (int i = 0; i < c.size; ++i) {
        float d[3];
        cube_face_direction(f, (i + 0.5f) / c.size, (j + 0.5f) / c.size, d);
        const double lat = std::asin(std::clamp(static_cast<double>(d[1]), -1.0, 1.0));
        double lon = std::atan2(-static_cast<double>(d[0]), static_cast<double>(d[2]));
        if (lon < 0) lon += 2 * pi;
        const double px = lon / (2 * pi) * w - 0.5, py = (0.5 - lat / pi) * h - 0.5;
        const int x0 = static_cast<int>(std::floor(px)), y0 = static_cast<int>(std::floor(py));
        const double fx = px - x0, fy = py - y0;
        for (int k = 0; k < 4; ++k) {
          const double top = texel(x0, y0, k) * (1 - fx) + texel(x0 + 1, y0, k) * fx;
          const double bottom = texel(x0, y0 + 1, k) * (1 - fx) + texel(x0 + 1, y0 + 1, k) * fx;
          face.pixels[(static_cast<size_t>(j) * c.size + i) * 4 + k] = static_cast<float>(top * (1 - fy) + bottom * fy);
        }
      }
  }
  return c;
}

}  // namespace ms
