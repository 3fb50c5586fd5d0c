#include "sweep/sweep_exact.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>

#include <glm/geometric.hpp>

#include "io/input_file.h"
#include "scene/camera_frame.h"
#include "shader/assemble.h"

namespace ms {
namespace {

// The text without comments and whitespace.
std::string squeeze(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      const size_t e = s.find("*/", i + 2);
      i = e == std::string_view::npos ? s.size() : e + 1;
    } else if (!std::isspace(static_cast<unsigned char>(s[i]))) {
      out += s[i];
    }
  }
  return out;
}

// A recursive-descent reader over the squeezed body of map().
struct Parser {
  const std::string& s;
  const std::vector<Material>& materials;
  size_t i = 0;
  std::map<std::string, std::vector<ExactSphere>> vars;

  bool eat(std::string_view tok) {
    if (s.compare(i, tok.size(), tok) != 0) return false;
    i += tok.size();
    return true;
  }
  bool number(double& v) {
    const char* b = s.c_str() + i;
    char* e = nullptr;
    v = std::strtod(b, &e);
    if (e == b || !std::isfinite(v)) return false;
    i += static_cast<size_t>(e - b);
    eat("f");
    return true;
  }
  bool ident(std::string& id) {
    const size_t b = i;
    while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
    id = s.substr(b, i - b);
    return !id.empty() && !std::isdigit(static_cast<unsigned char>(id[0]));
  }
  bool material(int& id) {
    std::string name;
    if (!eat("MAT_") || !ident(name)) return false;
    for (size_t k = 0; k < materials.size(); ++k) {
      std::string up = materials[k].name;
      for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (up == name) {
        id = static_cast<int>(k);
        return true;
      }
    }
    return false;
  }
  // vec2(sdSphere(p - vec3(x, y, z), r), MAT_X) or vec2(sdSphere(p, r), MAT_X)
  bool sphere(std::vector<ExactSphere>& out) {
    ExactSphere sp;
    if (!eat("vec2(sdSphere(p")) return false;
    if (eat("-vec3(")) {
      if (!number(sp.center.x) || !eat(",") || !number(sp.center.y) || !eat(",") || !number(sp.center.z) ||
          !eat(")"))
        return false;
    }
    if (!eat(",") || !number(sp.radius) || !eat("),") || !material(sp.material) || !eat(")")) return false;
    out.push_back(sp);
    return sp.radius > 0.0;
  }
  bool expr(std::vector<ExactSphere>& out) {
    if (s.compare(i, 5, "vec2(") == 0) return sphere(out);
    if (eat("opUnion(")) return expr(out) && eat(",") && expr(out) && eat(")");
    std::string id;
    if (!ident(id) || !vars.count(id)) return false;
    out.insert(out.end(), vars[id].begin(), vars[id].end());
    return true;
  }
  // Statements: "vec2 NAME = EXPR;" (squeezed: "vec2NAME=EXPR;") and "return EXPR;".
  bool body(std::vector<ExactSphere>& out) {
    while (i < s.size()) {
      if (eat("return")) return expr(out) && eat(";") && i == s.size();
      std::string id;
      if (!eat("vec2") || !ident(id) || !eat("=")) return false;
      std::vector<ExactSphere> v;
      if (!expr(v) || !eat(";")) return false;
      vars[id] = v;
    }
    return false;
  }
};

// Nearest hit in (0, tmax] of the ray o + t d (unit d) with the planes and spheres.
bool nearest(glm::dvec3 o, glm::dvec3 d, const std::vector<ExactSphere>& spheres, const std::vector<Plane>& planes,
             double& t) {
  bool hit = false;
  for (const Plane& pl : planes) {
    const glm::dvec3 n(pl.normal);
    const double h = glm::dot(o, n) + pl.offset, dn = glm::dot(d, n);
    const double th = h <= 0.0 ? 0.0 : (dn < 0.0 ? -h / dn : -1.0);
    if (th >= 0.0 && th <= t) {
      t = th;
      hit = true;
    }
  }
  for (const ExactSphere& sp : spheres) {
    const glm::dvec3 oc = o - sp.center;
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - sp.radius * sp.radius, disc = b * b - c;
    if (disc < 0.0) continue;
    const double ts = c <= 0.0 ? 0.0 : -b - std::sqrt(disc);  // inside: hit at once, as marching would
    if (ts >= 0.0 && ts <= t) {
      t = ts;
      hit = true;
    }
  }
  return hit;
}

}  // namespace

std::optional<std::vector<ExactSphere>> parse_sphere_map(std::string_view map_glsl,
                                                         const std::vector<Material>& materials, std::string* why) {
  const std::string all = squeeze(map_glsl);
  const std::string head = "vec2map(vec3p){";
  const size_t at = all.find(head);
  auto fail = [&](const std::string& reason) -> std::optional<std::vector<ExactSphere>> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (at == std::string::npos) return fail("no 'vec2 map(vec3 p)' found");
  // The body up to the matching brace; nothing may follow map() (helpers
  // before it would be used by it, and we cannot see through them).
  size_t depth = 1, e = at + head.size();
  for (; e < all.size() && depth > 0; ++e) depth += all[e] == '{' ? 1 : all[e] == '}' ? -1 : 0;
  if (depth != 0) return fail("unbalanced braces in map()");
  if (at != 0 || e != all.size()) return fail("the map file has code besides map()");
  const std::string body = all.substr(at + head.size(), e - 1 - (at + head.size()));
  Parser p{body, materials, 0, {}};
  std::vector<ExactSphere> spheres;
  if (!p.body(spheres)) return fail("map() is not a union of constant spheres");
  return spheres;
}

ExactDepth exact_depth(const Camera& cam, int width, int height, const std::vector<ExactSphere>& spheres,
                       const std::vector<Plane>& planes, double max_distance) {
  // camera.glsl's cameraRay() in double, from the frame the shader gets.
  const CameraFrame cf = camera_frame(cam);
  const glm::dvec3 pos(cam.position), fw(cf.forward), right(cf.right), upv(cf.up);
  const double th = cf.tan_half_fov;
  ExactDepth out;
  out.width = width;
  out.height = height;
  out.hit.assign(static_cast<size_t>(width) * height, 0);
  out.t.assign(out.hit.size(), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // Pixel centre; GL's row 0 is the bottom one, images store the top first.
      const double px = x + 0.5, py = (height - 1 - y) + 0.5;
      const double u = (2.0 * px - width) / height, v = (2.0 * py - height) / height;
      const glm::dvec3 d = glm::normalize(fw + th * (u * right + v * upv));
      double t = max_distance;
      const size_t i = static_cast<size_t>(y) * width + x;
      if (nearest(pos, d, spheres, planes, t)) {
        out.hit[i] = 1;
        out.t[i] = t;
      }
    }
  return out;
}

std::optional<std::vector<ExactSphere>> exact_spheres(const Scene& scene, std::string* why) {
  if (!input_file_problem(scene.map_file).empty()) {
    if (why) *why = "cannot read the map file";
    return std::nullopt;
  }
  const std::string text = read_input_file(scene.map_file, "map file");
  return parse_sphere_map(text, scene.materials, why);
}

std::optional<ExactDepth> exact_reference(const Scene& scene, int width, int height, double max_distance,
                                          std::string* why) {
  const auto spheres = exact_spheres(scene, why);
  if (!spheres) return std::nullopt;
  return exact_depth(scene.camera, width, height, *spheres, scene.planes, max_distance);
}

std::vector<std::pair<std::string, std::string>> exact_sphere_defines(const std::vector<ExactSphere>& spheres) {
  std::string list, mats;
  for (const ExactSphere& sp : spheres) {
    if (!list.empty()) {
      list += ", ";
      mats += ", ";
    }
    list += "vec4(" + glsl_float(static_cast<float>(sp.center.x)) + ", " + glsl_float(static_cast<float>(sp.center.y)) +
            ", " + glsl_float(static_cast<float>(sp.center.z)) + ", " + glsl_float(static_cast<float>(sp.radius)) + ")";
    mats += std::to_string(sp.material);
  }
  return {{"EXACT_SPHERES", std::to_string(spheres.size())}, {"EXACT_SPHERE_LIST", list},
          {"EXACT_SPHERE_MATERIALS", mats}};
}

}  // namespace ms
