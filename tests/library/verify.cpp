#include "verify.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace ms::test {
namespace {

const char* const kLibraryFiles[] = {"primitives.glsl", "primitives2d.glsl", "primitives_cones.glsl",
                                     "primitives_poly.glsl", "operators.glsl", "combinators.glsl",
                                     "domain.glsl", "modifiers.glsl", "noise.glsl"};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool is_number(const std::string& s, double* v) {
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0') return false;
  *v = d;
  return true;
}

// Nearest-point queries against a point set: a k-d tree (median splits).
class Nearest {
 public:
  explicit Nearest(std::vector<glm::vec3> pts) : pts_(std::move(pts)) {
    idx_.resize(pts_.size());
    axis_.assign(pts_.size(), 0);
    for (size_t i = 0; i < idx_.size(); ++i) idx_[i] = static_cast<int>(i);
    build(0, static_cast<int>(idx_.size()));
  }
  float distance(const glm::vec3& q) const {
    float best = INFINITY;
    search(0, static_cast<int>(idx_.size()), q, best);
    return std::sqrt(best);
  }

 private:
  // Node [lo, hi): its median idx_[mid] splits along axis_[mid].
  void build(int lo, int hi) {
    if (hi - lo <= 1) return;
    glm::vec3 mn(INFINITY), mx(-INFINITY);
    for (int i = lo; i < hi; ++i) {
      mn = glm::min(mn, pts_[idx_[i]]);
      mx = glm::max(mx, pts_[idx_[i]]);
    }
    const glm::vec3 ext = mx - mn;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    const int mid = (lo + hi) / 2;
    std::nth_element(idx_.begin() + lo, idx_.begin() + mid, idx_.begin() + hi,
                     [&](int a, int b) { return pts_[a][axis] < pts_[b][axis]; });
    axis_[mid] = axis;
    build(lo, mid);
    build(mid + 1, hi);
  }
  void search(int lo, int hi, const glm::vec3& q, float& best) const {
    if (hi <= lo) return;
    const int mid = (lo + hi) / 2;
    const glm::vec3& p = pts_[idx_[mid]];
    const glm::vec3 d = p - q;
    best = std::min(best, glm::dot(d, d));
    if (hi - lo == 1) return;
    const int axis = axis_[mid];
    const float delta = q[axis] - p[axis];
    const bool left_first = delta < 0.0f;
    if (left_first) search(lo, mid, q, best); else search(mid + 1, hi, q, best);
    if (delta * delta < best) { if (left_first) search(mid + 1, hi, q, best); else search(lo, mid, q, best); }
  }
  std::vector<glm::vec3> pts_;
  std::vector<int> idx_;
  std::vector<int> axis_;
};

std::string fmt_point(const glm::vec3& p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

}  // namespace

std::vector<Claim> library_claims(const std::string& shader_dir) {
  const std::regex guard(R"(^#if !defined\(MS_LIBRARY_SUBSET\) \|\| defined\(USE_([A-Z0-9]+)\)\s*$)");
  const std::regex def(R"(^\s*(?:float|vec2|vec3|vec4|int|bool)\s+(\w+)\s*\()");
  const std::regex tag(R"(\[(exact outside|exact|bound|unsigned|noise|index|helper)(?:; L = ([^\]]+))?\])");
  std::vector<Claim> out;
  for (const char* file : kLibraryFiles) {
    std::ifstream in(shader_dir + "/" + file);
    if (!in) throw std::runtime_error(std::string("cannot read ") + file);
    std::string line, name, comments;
    int n = 0, guard_line = 0;
    bool in_block = false, found = false;
    std::smatch m;
    while (std::getline(in, line)) {
      ++n;
      if (std::regex_match(line, m, guard)) {
        in_block = true;
        found = false;
        name = m[1];
        comments.clear();
        guard_line = n;
        continue;
      }
      if (!in_block) continue;
      if (line.rfind("#endif", 0) == 0) {
        if (!found) throw std::runtime_error(std::string(file) + ":" + std::to_string(guard_line) + ": USE_" + name + " guards no function");
        in_block = false;
        continue;
      }
      if (found) continue;
      if (line.find("//") != std::string::npos) comments += line.substr(line.find("//") + 2) + " ";
      if (std::regex_search(line, m, def)) {
        if (upper(m[1]) != name)
          throw std::runtime_error(std::string(file) + ":" + std::to_string(n) + ": " + std::string(m[1]) +
                                   " under the guard USE_" + name);
        std::smatch t;
        if (!std::regex_search(comments, t, tag))
          throw std::runtime_error(std::string(file) + ":" + std::to_string(n) + ": " + std::string(m[1]) +
                                   "'s comment has no claim tag such as [exact; L = 1]");
        out.push_back({m[1], file, t[1], t[2], n});
        found = true;
      }
    }
  }
  return out;
}

std::vector<Case> load_cases(const std::string& path, const std::vector<Claim>& claims) {
  const toml::table t = toml::parse_file(path);
  const toml::array* arr = t["case"].as_array();
  if (!arr) throw std::runtime_error(path + ": no [[case]] entries");
  std::vector<Case> out;
  int i = 0;
  for (const toml::node& node : *arr) {
    const toml::table& e = *node.as_table();
    const std::string where = path + ": case[" + std::to_string(i++) + "]";
    for (const auto& [k, v] : e) {
      static const std::vector<std::string> known = {"function", "condition", "claim", "lipschitz", "box", "center",
                                                     "dims", "tolerance", "f", "inside", "skip", "check",
                                                     "surface", "helpers"};
      if (std::find(known.begin(), known.end(), std::string(k.str())) == known.end())
        throw std::runtime_error(where + ": unknown key '" + std::string(k.str()) + "'");
    }
    Case c;
    c.function = e["function"].value_or(std::string());
    const auto claim = std::find_if(claims.begin(), claims.end(), [&](const Claim& x) { return x.function == c.function; });
    if (claim == claims.end()) throw std::runtime_error(where + ": '" + c.function + "' is not a guarded library function");
    c.condition = e["condition"].value_or(std::string());
    c.kind = claim->kind;
    if (e.contains("claim")) {
      if (c.condition.empty()) throw std::runtime_error(where + ": 'claim' overrides the tag only with a 'condition'");
      c.kind = e["claim"].value_or(std::string());
    }
    double tag_l = 0.0;
    const bool numeric = is_number(claim->lipschitz, &tag_l);
    if (e.contains("lipschitz")) {
      c.lipschitz = e["lipschitz"].value_or(0.0);
      if (numeric && c.condition.empty() && c.lipschitz != tag_l)
        throw std::runtime_error(where + ": lipschitz " + std::to_string(c.lipschitz) + " differs from the tag's " +
                                 claim->lipschitz + " (give a condition for a configuration of its own)");
    } else if (numeric) {
      c.lipschitz = tag_l;
    } else if (!claim->lipschitz.empty()) {
      throw std::runtime_error(where + ": the tag's L is '" + claim->lipschitz + "': give the case's number");
    }
    glm::vec3 half(1.0f), centre(0.0f);
    if (const toml::array* b = e["box"].as_array())
      for (int k = 0; k < 3; ++k) half[k] = static_cast<float>((*b)[k].value_or(1.0));
    if (const toml::array* b = e["center"].as_array())
      for (int k = 0; k < 3; ++k) centre[k] = static_cast<float>((*b)[k].value_or(0.0));
    c.box = {centre - half, centre + half};
    c.dims = e["dims"].value_or(3);
    if (c.dims == 2) c.box.lo.z = c.box.hi.z = 0.0f;
    c.tolerance = e["tolerance"].value_or(0.0);
    c.src.f = e["f"].value_or(std::string("0.0"));
    c.src.inside = e["inside"].value_or(std::string("false"));
    c.src.skip = e["skip"].value_or(std::string("false"));
    c.src.check = e["check"].value_or(std::string("0.0"));
    c.src.surface = e["surface"].value_or(std::string("vec3(0.0)"));
    c.src.helpers = e["helpers"].value_or(std::string());
    const bool signed_kind = c.kind == "exact" || c.kind == "exact outside" || c.kind == "bound";
    if (signed_kind && !e.contains("inside")) throw std::runtime_error(where + ": a signed claim needs 'inside'");
    if (c.kind == "unsigned" && !e.contains("surface")) throw std::runtime_error(where + ": 'unsigned' needs 'surface'");
    if ((c.kind == "index" || c.kind == "helper") && !e.contains("check"))
      throw std::runtime_error(where + ": '" + c.kind + "' needs 'check'");
    out.push_back(c);
  }
  return out;
}

CaseResult verify_case(const Case& c, const std::string& shader_dir) {
  const GpuCase gpu(shader_dir, c.src);
  CaseResult r;
  std::mt19937 rng(static_cast<unsigned>(std::hash<std::string>{}(c.function + "|" + c.condition)));
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  const glm::vec3 size = c.box.hi - c.box.lo;
  const float scale = std::max(size.x, std::max(size.y, size.z)) * 0.5f;
  auto random_point = [&] {
    return c.box.lo + size * glm::vec3(u01(rng), u01(rng), c.dims == 2 ? 0.0f : u01(rng));
  };
  auto fail = [&](const std::string& what) {
    if (r.first_failure.empty()) r.first_failure = what;
  };

  // Points for sign and distance, then pairs for the Lipschitz bound: half
  // short (the local slope), half anywhere in the box.
  const int kPoints = 3000, kPairs = 4000;
  std::vector<glm::vec3> pts;
  for (int i = 0; i < kPoints; ++i) pts.push_back(random_point());
  for (int i = 0; i < kPairs; ++i) {
    const glm::vec3 a = random_point();
    glm::vec3 b = random_point();
    if (i % 2 == 0) {
      glm::vec3 d(u01(rng) - 0.5f, u01(rng) - 0.5f, c.dims == 2 ? 0.0f : u01(rng) - 0.5f);
      const float len = scale * 0.002f * std::pow(25.0f, u01(rng));  // 0.002 .. 0.05 of the box
      b = a + glm::normalize(d + glm::vec3(1e-6f)) * len;
    }
    pts.push_back(a);
    pts.push_back(b);
  }
  const std::vector<Sample> s = gpu.eval(pts);

  const double L = c.lipschitz;
  const bool is_noise = c.kind == "noise";
  if (!c.kind.empty() && c.kind != "index" && c.kind != "helper") {
    for (int i = 0; i < kPairs; ++i) {
      const glm::vec3 a = pts[kPoints + 2 * i], b = pts[kPoints + 2 * i + 1];
      const double fa = s[kPoints + 2 * i].f, fb = s[kPoints + 2 * i + 1].f;
      const double dp = glm::length(a - b), df = std::abs(fa - fb);
      if (dp < 1e-3 * scale) continue;
      ++r.lipschitz_pairs;
      r.lipschitz_max = std::max(r.lipschitz_max, df / dp);
      const double allowed = L * dp * (1.0 + 1e-3) + 2e-5 * (1.0 + std::abs(fa) + std::abs(fb));
      if (!(df <= allowed)) {
        ++r.lipschitz_violations;
        fail("|f(a) - f(b)| = " + std::to_string(df) + " > L |a - b| = " + std::to_string(L * dp) + " at a = " +
             fmt_point(a) + ", b = " + fmt_point(b));
      }
    }
  }

  if (c.kind == "exact" || c.kind == "exact outside" || c.kind == "bound" || c.kind == "unsigned") {
    const int grid = c.dims == 2 ? 1024 : 96, steps = c.dims == 2 ? 512 : 160;
    const std::vector<glm::vec3> zs = c.kind == "unsigned" ? gpu.surface(400) : gpu.zeros(c.box, grid, steps, c.dims);
    r.surface_samples = static_cast<int>(zs.size());
    if (zs.empty()) fail("no surface found in the box");
    const float h = c.kind == "unsigned" ? scale / 200.0f : 2.0f * scale / grid;  // sample spacing
    const Nearest nearest(zs);
    // Exact claims: move each point by |f| against the gradient; there the
    // field must vanish. With the bound check (nothing nearer than |f|) that
    // makes |f| the distance, to float precision rather than the sampling's.
    // The gradient comes from differences on either side per axis: near a
    // ridge of the field (its medial axis) the taps on q's side of it give
    // q's gradient, so every combination of sides is tried.
    std::vector<int> exact_points;
    std::vector<glm::vec3> taps;
    const float eps = 2e-3f * scale;
    const int axes = c.dims == 2 ? 2 : 3;
    for (int i = 0; i < kPoints; ++i) {
      const float f = s[i].f;
      if (std::abs(f) < 2.0f * h) continue;
      if (!(c.kind == "exact" || c.kind == "unsigned" || (c.kind == "exact outside" && f > 0.0f))) continue;
      exact_points.push_back(i);
      for (int k = 0; k < 3; ++k) {
        glm::vec3 e(0.0f);
        e[k] = eps;
        taps.push_back(pts[i] + e);
        taps.push_back(pts[i] - e);
      }
    }
    const std::vector<Sample> ts = gpu.eval(taps);
    std::vector<glm::vec3> projected;
    std::vector<int> projected_of;  // index into exact_points
    for (size_t n = 0; n < exact_points.size(); ++n) {
      const float f0 = s[exact_points[n]].f;
      for (int combo = 0; combo <= (1 << axes); ++combo) {  // the last: central differences
        glm::vec3 g(0.0f);
        for (int k = 0; k < axes; ++k) {
          const float fp = ts[6 * n + 2 * k].f, fm = ts[6 * n + 2 * k + 1].f;
          g[k] = combo == (1 << axes) ? (fp - fm) / (2.0f * eps) : (combo >> k) & 1 ? (fp - f0) / eps : (f0 - fm) / eps;
        }
        const float len = glm::length(g);
        if (std::abs(len - 1.0f) > 0.03f) continue;  // not a distance's slope from these taps
        projected.push_back(pts[exact_points[n]] - f0 * g / len);
        projected_of.push_back(static_cast<int>(n));
      }
    }
    const std::vector<Sample> ps = gpu.eval(projected);
    std::vector<double> best(exact_points.size(), INFINITY);
    for (size_t m = 0; m < projected.size(); ++m)
      best[projected_of[m]] = std::min(best[projected_of[m]], static_cast<double>(std::abs(ps[m].f)));
    // Within a few taps of where ridges meet (a fold's axis, a cone's tip)
    // no side's differences can be trusted: up to 0.3% of the points may stay
    // unresolved (they still pass the bound check below).
    std::vector<std::string> unresolved;
    for (size_t n = 0; n < exact_points.size(); ++n) {
      const glm::vec3& q = pts[exact_points[n]];
      const double af = std::abs(s[exact_points[n]].f);
      if (std::isinf(best[n])) {
        unresolved.push_back("no side's differences at " + fmt_point(q) +
                             " give a gradient of length 1, as an exact distance's is");
        continue;
      }
      // A direction off by theta misses a nearest vertex by |f| theta: the
      // taps' float noise and curvature allow about 5e-3 rad.
      if (best[n] > 5e-4 * scale + 5e-3 * af + c.tolerance) {
        unresolved.push_back("f = " + std::to_string(s[exact_points[n]].f) + " at " + fmt_point(q) + ", but |f| = " +
                             std::to_string(best[n]) + " (at best) where that moves it along the gradient");
        continue;
      }
      r.distance_error = std::max(r.distance_error, best[n]);
    }
    r.exact_points = static_cast<int>(exact_points.size());
    r.unresolved_points = static_cast<int>(unresolved.size());
    if (unresolved.size() > std::max<size_t>(1, exact_points.size() * 3 / 1000)) {
      r.distance_violations += static_cast<int>(unresolved.size());
      fail(std::to_string(unresolved.size()) + " of " + std::to_string(exact_points.size()) +
           " points are not at distance |f| from the surface; first: " + unresolved[0]);
    }
    for (int i = 0; i < kPoints; ++i) {
      const double f = s[i].f, af = std::abs(f);
      const glm::vec3& q = pts[i];
      if (af < 2.0 * h) continue;  // the sampling cannot resolve it
      const double d = nearest.distance(q);
      ++r.distance_points;
      // Never farther than the nearest zero found: a bound on that is a
      // bound on the true distance, which can only be smaller.
      const double over = af - L * d;
      if (c.kind == "bound" || (c.kind == "exact outside" && f < 0.0)) r.distance_error = std::max(r.distance_error, std::max(over, 0.0));
      if (over > 1e-4 * scale + c.tolerance) {
        ++r.distance_violations;
        fail("|f| = " + std::to_string(af) + " exceeds L x the distance to the surface, " + std::to_string(L * d) +
             ", at " + fmt_point(q));
      }
    }
  }
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    const Sample& x = s[i];
    if (i >= kPoints && !is_noise) break;
    bool bad = false;
    if (c.kind == "unsigned") bad = x.f < -1e-6f;
    else if (is_noise) bad = !(std::abs(x.f) <= 1.0f + 1e-5f);
    else if (c.kind == "index" || c.kind == "helper") bad = !(std::abs(x.check) <= 1e-4 + c.tolerance);
    else if (x.skip || std::abs(x.f) < 1e-4f * scale) continue;
    else bad = (x.f < 0.0f) != x.inside;
    ++r.sign_points;
    if (bad) {
      ++r.sign_violations;
      fail("f = " + std::to_string(x.f) + (c.kind == "index" || c.kind == "helper" ? ", check = " + std::to_string(x.check) : "") +
           (x.inside ? " (inside)" : " (outside)") + " at " + fmt_point(pts[i]));
    }
  }
  return r;
}

nlohmann::json to_json(const Case& c, const CaseResult& r) {
  return {{"function", c.function},
          {"condition", c.condition},
          {"claim", c.kind},
          {"lipschitz", c.lipschitz},
          {"lipschitz_pairs", r.lipschitz_pairs},
          {"lipschitz_max", r.lipschitz_max},
          {"lipschitz_violations", r.lipschitz_violations},
          {"distance_points", r.distance_points},
          {"surface_samples", r.surface_samples},
          {"distance_error", r.distance_error},
          {"exact_points", r.exact_points},
          {"unresolved_points", r.unresolved_points},
          {"distance_violations", r.distance_violations},
          {"sign_points", r.sign_points},
          {"sign_violations", r.sign_violations},
          {"passed", r.passed()}};
}

}  // namespace ms::test
