#include "preprocess/confine.h"

#include "core/error.h"

namespace ms {

namespace fs = std::filesystem;

std::vector<fs::path> media_roots(const fs::path& scene_file, const fs::path& media_flag_dir,
                                  const std::vector<fs::path>& allow_include) {
  std::error_code ec;
  std::vector<fs::path> roots = {fs::absolute(scene_file, ec).parent_path()};
  if (!media_flag_dir.empty()) roots.push_back(media_flag_dir);
  roots.insert(roots.end(), allow_include.begin(), allow_include.end());
  return roots;
}

void confine_media(const fs::path& file, const std::vector<fs::path>& roots, const std::string& what,
                   const std::string& origin, const std::string& key) {
  const fs::path c = resolved_path(file);
  if (inside_roots(c, resolved_roots(roots))) return;
  fail_input(what + " resolves to " + display_path(c) + ", outside the directories media may read", origin, 0, key,
             "allowed: " + describe_roots(roots) + "; widen with --allow-include DIR");
}

}  // namespace ms
