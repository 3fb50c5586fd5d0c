#include "io/path_roots.h"

#include <algorithm>
#include <system_error>

namespace ms {

namespace fs = std::filesystem;

std::string display_path(const fs::path& p) {
  if (p.empty()) return {};
  std::error_code ec;
  fs::path abs = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) abs = p;
  fs::path cwd = fs::current_path(ec);
  if (!ec) {
    fs::path ccwd = fs::weakly_canonical(cwd, ec);
    if (!ec) cwd = ccwd;
    fs::path rel = abs.lexically_relative(cwd);
    if (!rel.empty() && *rel.begin() != ".." && rel != ".") return rel.generic_string();
  }
  return abs.generic_string();
}

fs::path resolved_path(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  if (ec) a = p;
  fs::path c = fs::weakly_canonical(a, ec);
  return ec ? a.lexically_normal() : c;
}

bool inside_roots(const fs::path& canonical, const std::vector<fs::path>& canonical_roots) {
  for (const fs::path& root : canonical_roots) {
    const fs::path rel = canonical.lexically_relative(root);
    if (!rel.empty() && *rel.begin() != "..") return true;
  }
  return false;
}

std::vector<fs::path> resolved_roots(const std::vector<fs::path>& roots) {
  std::vector<fs::path> out;
  for (const fs::path& r : roots)
    if (!r.empty()) out.push_back(resolved_path(r));
  return out;
}

bool within_roots(const fs::path& p, const std::vector<fs::path>& roots) {
  return inside_roots(resolved_path(p), resolved_roots(roots));
}

std::string describe_roots(const std::vector<fs::path>& roots) {
  std::vector<std::string> names;
  for (const fs::path& r : resolved_roots(roots)) {
    std::string n = display_path(r);
    if (n.empty()) n.push_back('.');
    if (n.back() != '/') n.push_back('/');
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out.append(i + 1 == names.size() ? " and " : ", ");
    out.append(names[i]);
  }
  return out;
}

}  // namespace ms
