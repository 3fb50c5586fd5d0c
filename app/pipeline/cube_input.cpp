#include "pipeline/cube_input.h"

#include "core/error.h"
#include "io/image_io.h"
#include "io/input_file.h"
#include "pipeline/project_passes.h"
#include "preprocess/confine.h"

namespace ms {
namespace fs = std::filesystem;

CubeFaces cube_standin(MissingMedia kind) {
  CubeFaces c;
  c.size = kind == MissingMedia::black ? 1 : 64;
  for (int f = 0; f < 6; ++f) {
    Image& img = c.faces[f];
    img.width = img.height = c.size;
    img.channels = {"R", "G", "B", "A"};
    img.pixels.resize(static_cast<size_t>(c.size) * c.size * 4);
    for (int y = 0; y < c.size; ++y)
      for (int x = 0; x < c.size; ++x)
        for (int k = 0; k < 4; ++k)
          img.pixels[(static_cast<size_t>(y) * c.size + x) * 4 + k] =
              kind == MissingMedia::black ? (k == 3 ? 1.0f : 0.0f)
                                          : static_cast<float>(volume_noise_byte(x, y, f, k, c.size)) / 255.0f;
  }
  return c;
}

std::shared_ptr<const CubeFaces> load_cube_input(const ProjectInput& in, const ShadertoySettings& s,
                                                 const std::vector<fs::path>& roots, const std::string& where,
                                                 const std::string& origin,
                                                 std::vector<std::string>& warnings,
                                                 std::map<fs::path, std::shared_ptr<const CubeFaces>>& cache) {
  // Face 0: the scene's path, else the src's file name in the media directory.
  fs::path first = in.file;
  if (first.empty() && !s.media_dir.empty() && !fs::path(in.src).filename().empty())
    first = s.media_dir / fs::path(in.src).filename();
  // The VS Code extension's "sky_{}.png": the faces sky_px.png .. sky_nz.png.
  std::array<fs::path, 6> files = cube_face_files(first);
  if (in.src.find("{}") != std::string::npos) {  // a path the loader resolved
    files = cube_wildcard_files(in.src);
    first = files[0];
  }
  // Every candidate is judged before any is looked at: a face is a file read like any other medium.
  if (!first.empty())
    for (int i = 0; i < 6; ++i)
      confine_media(files[i], roots, where + ": cubemap '" + in.src + "' face '" + files[i].filename().string() + "'",
                    origin, where);
  // One file of EXR or HDR with no "_1" beside it: an equirectangular image.
  const bool wildcard = in.src.find("{}") != std::string::npos;
  const bool equirect = !wildcard && !first.empty() && is_float_image_name(first) && input_file_problem(first).empty() &&
                        !input_file_problem(files[1]).empty();
  fs::path missing;
  for (int i = 0; i < (equirect ? 1 : 6) && missing.empty(); ++i)
    if (first.empty() || !input_file_problem(files[i]).empty()) missing = first.empty() ? fs::path(in.src) : files[i];
  if (!missing.empty()) {
    const std::string what = where + ": cubemap '" + in.src + "'" +
                             (missing == fs::path(in.src) ? "" : " face '" + missing.filename().string() + "'");
    if (s.missing_media == MissingMedia::error)
      fail_input(what + " is not in the media directory", origin, 0, where,
                 (s.media_dir.empty() && in.file.empty() ? std::string("no media directory")
                                                         : "looked for " + display_path(missing)) +
                     "; a cubemap is six files, <name>, <name>_1 .. <name>_5, or one equirectangular .exr/.hdr; "
                     "--missing-media noise|black stands in for it");
    const bool noise = s.missing_media == MissingMedia::noise;
    warnings.push_back(what + " is missing; " + (noise ? "generated noise stands in on each face" : "black stands in"));
    return std::make_shared<const CubeFaces>(cube_standin(s.missing_media));
  }
  auto& c = cache[first];
  if (!c)
    c = std::make_shared<const CubeFaces>(equirect ? equirect_to_cube(read_image(first), 0, first.string())
                                                   : read_cube_faces(files));
  return c;
}

}  // namespace ms
