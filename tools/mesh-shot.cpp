// mesh-shot: a flat-shaded GL picture of a mesh, for docs/mesh.md.
//
//   mesh-shot MESH.ply -o out.png [--size 640x360] --eye x,y,z --target x,y,z
//             [--up x,y,z] [--fov 45] [--scene SCENE.toml] [--wire]
//
// Reads the binary PLY `marchstudio mesh` writes (float x, y, z, optional
// float nx, ny, nz, ushort material; faces as list uchar uint): anything
// else is one line and exit 2. Faces are flat (normals from a geometry
// shader, the file's are skipped: the picture shows the facets), lit by a key light fixed
// to the camera plus ambient, coloured by material id; --wire draws their
// edges. 4x MSAA, resolved before the read-back. --scene takes the camera
// from the scene's [camera].
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "gl/context.h"
#include "gl/gl.h"
#include "io/image.h"
#include "io/image_io.h"
#include "scene/load.h"

namespace {

using ms::fail_input;
using ms::fail_system;

struct Mesh {
  std::vector<float> xyz;
  std::vector<std::uint16_t> material;
  std::vector<std::uint32_t> index;
};

struct Options {
  std::string mesh, out, scene;
  int width = 640, height = 360;
  ms::Camera cam;
  bool eye = false, target = false, wire = false;
};

struct PlyLayout {
  std::size_t stride = 12;  // bytes per vertex
  bool material = false;    // a ushort at stride - 2
};

// The header, up to end_header: the exporter's layout (normals and material optional).
PlyLayout read_ply_header(std::istream& in, const std::string& path, std::size_t& nv, std::size_t& nf) {
  std::string line, element;
  std::vector<std::string> props;
  if (!std::getline(in, line) || line != "ply") fail_input("not a PLY file", path);
  if (!std::getline(in, line) || line != "format binary_little_endian 1.0")
    fail_input("only binary_little_endian 1.0 PLY is read, got '" + line + "'", path);
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream w(line);
    std::string word;
    w >> word;
    if (word == "comment" || word == "obj_info") continue;
    if (word == "element") {
      std::size_t n = 0;
      w >> element >> n;
      if (element == "vertex" && props.empty()) nv = n;
      else if (element == "face" && !props.empty()) nf = n;
      else fail_input("expected the elements vertex, then face; got '" + line + "'", path);
    } else if (word == "property" && element == "vertex") {
      props.push_back(line);
    } else if (word != "property" || element != "face" ||
               (line != "property list uchar uint vertex_indices" && line != "property list uchar int vertex_indices")) {
      fail_input("unexpected PLY header line '" + line + "'", path, 0, {},
                 "faces are 'property list uchar uint vertex_indices'");
    }
  }
  if (line != "end_header") fail_input("the PLY header has no end_header", path);
  std::vector<std::string> want = {"property float x", "property float y", "property float z"};
  PlyLayout l;
  if (props.size() >= 6 && props[3] == "property float nx") {
    want.insert(want.end(), {"property float nx", "property float ny", "property float nz"});
    l.stride += 12;
  }
  l.material = props.size() == want.size() + 1 && props.back() == "property ushort material";
  if (l.material) {
    want.push_back(props.back());
    l.stride += 2;
  }
  if (props != want) fail_input("vertices must be float x, y, z, optionally nx, ny, nz and ushort material", path);
  return l;
}

Mesh read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_input("cannot open the mesh", path);
  std::size_t nv = 0, nf = 0;
  const PlyLayout layout = read_ply_header(in, path, nv, nf);
  const std::size_t stride = layout.stride;
  std::vector<char> raw(nv * stride);
  in.read(raw.data(), static_cast<std::streamsize>(raw.size()));
  Mesh m;
  m.xyz.resize(nv * 3);
  m.material.resize(nv, 0);
  for (std::size_t i = 0; i < nv; ++i) {
    std::memcpy(&m.xyz[i * 3], &raw[i * stride], 12);
    if (layout.material) std::memcpy(&m.material[i], &raw[i * stride + stride - 2], 2);
  }
  raw.resize(nf * 13);
  in.read(raw.data(), static_cast<std::streamsize>(raw.size()));
  if (!in) fail_input("the PLY ends early", path);
  m.index.resize(nf * 3);
  for (std::size_t i = 0; i < nf; ++i) {
    if (raw[i * 13] != 3) fail_input("face " + std::to_string(i) + " is not a triangle", path);
    std::memcpy(&m.index[i * 3], &raw[i * 13 + 1], 12);
  }
  for (std::uint32_t k : m.index)
    if (k >= nv) fail_input("a face names vertex " + std::to_string(k) + " of " + std::to_string(nv), path);
  if (nf == 0) fail_input("the mesh has no faces", path);
  return m;
}

glm::vec3 parse_vec3(const std::string& s, const char* flag) {
  glm::vec3 v;
  char tail = 0;
  if (std::sscanf(s.c_str(), "%f,%f,%f%c", &v.x, &v.y, &v.z, &tail) != 3)
    fail_input(std::string("expected x,y,z, got '") + s + "'", {}, 0, flag);
  return v;
}

Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail_input("needs a value", {}, 0, a);
      return argv[++i];
    };
    if (a == "-o" || a == "--output") o.out = value();
    else if (a == "--size") {
      if (std::sscanf(value().c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1 ||
          o.width > 8192 || o.height > 8192)
        fail_input("expected WxH within 8192x8192", {}, 0, a);
    } else if (a == "--eye") o.cam.position = parse_vec3(value(), "--eye"), o.eye = true;
    else if (a == "--target") o.cam.target = parse_vec3(value(), "--target"), o.target = true;
    else if (a == "--up") o.cam.up = parse_vec3(value(), "--up");
    else if (a == "--fov") o.cam.fov_deg = std::stof(value());
    else if (a == "--scene") o.scene = value();
    else if (a == "--wire") o.wire = true;
    else if (!a.empty() && a[0] == '-') fail_input("unknown flag", {}, 0, a, "see the top of tools/mesh-shot.cpp");
    else if (o.mesh.empty()) o.mesh = a;
    else fail_input("one mesh only, got a second: " + a);
  }
  if (o.mesh.empty() || o.out.empty()) fail_input("usage: mesh-shot MESH.ply -o out.png [--size WxH] --eye x,y,z --target x,y,z");
  if (!o.scene.empty()) o.cam = ms::load_scene(o.scene).camera;
  else if (!o.eye || !o.target) fail_input("give --eye and --target, or --scene");
  if (!(o.cam.fov_deg > 0.0f && o.cam.fov_deg < 180.0f)) fail_input("must be in (0, 180)", {}, 0, "--fov");
  return o;
}

const char* kVert = R"(#version 450 core
layout(location = 0) in vec3 pos;
layout(location = 1) in uint mat;
uniform mat4 view_proj;
out vec3 v_world;
flat out uint v_mat;
void main() { v_world = pos; v_mat = mat; gl_Position = view_proj * vec4(pos, 1.0); }
)";

// One normal per face, and barycentrics for the edges.
const char* kGeom = R"(#version 450 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 v_world[];
flat in uint v_mat[];
flat out vec3 g_normal;
flat out uint g_mat;
out vec3 g_bary;
void main() {
  vec3 n = normalize(cross(v_world[1] - v_world[0], v_world[2] - v_world[0]));
  for (int i = 0; i < 3; ++i) {
    g_normal = n; g_mat = v_mat[0];
    g_bary = vec3(i == 0, i == 1, i == 2);
    gl_Position = gl_in[i].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
)";

const char* kFrag = R"(#version 450 core
flat in vec3 g_normal;
flat in uint g_mat;
in vec3 g_bary;
uniform vec3 key_dir;  // towards the light, world space
uniform bool wire;
out vec4 color;
const vec3 palette[6] = vec3[](vec3(0.80, 0.35, 0.25), vec3(0.62, 0.64, 0.68), vec3(0.85, 0.55, 0.20),
                               vec3(0.20, 0.45, 0.85), vec3(0.35, 0.65, 0.35), vec3(0.70, 0.45, 0.75));
void main() {
  // A back face seen (an open or inside-out mesh) is lit as a front face.
  vec3 n = gl_FrontFacing ? g_normal : -g_normal;
  vec3 albedo = palette[g_mat % 6u];
  vec3 c = albedo * (0.22 + 0.78 * max(dot(n, key_dir), 0.0));
  if (wire) {
    vec3 d = g_bary / max(fwidth(g_bary), vec3(1e-6));
    c = mix(c * 0.25, c, smoothstep(0.5, 1.5, min(d.x, min(d.y, d.z))));
  }
  color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
)";

GLuint compile(GLenum type, const char* src) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    fail_system(std::string("shader compile failed: ") + log);
  }
  return s;
}

GLuint make_program() {
  const GLuint p = glCreateProgram();
  const std::pair<GLenum, const char*> stages[] = {
      {GL_VERTEX_SHADER, kVert}, {GL_GEOMETRY_SHADER, kGeom}, {GL_FRAGMENT_SHADER, kFrag}};
  for (const auto& [type, src] : stages) glAttachShader(p, compile(type, src));
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) fail_system("shader link failed");
  return p;
}

GLuint upload(const Mesh& m) {
  GLuint vao = 0, buf[3] = {};
  glCreateVertexArrays(1, &vao);
  glCreateBuffers(3, buf);
  glNamedBufferStorage(buf[0], static_cast<GLsizeiptr>(m.xyz.size() * 4), m.xyz.data(), 0);
  glNamedBufferStorage(buf[1], static_cast<GLsizeiptr>(m.material.size() * 2), m.material.data(), 0);
  glNamedBufferStorage(buf[2], static_cast<GLsizeiptr>(m.index.size() * 4), m.index.data(), 0);
  glVertexArrayVertexBuffer(vao, 0, buf[0], 0, 12);
  glVertexArrayVertexBuffer(vao, 1, buf[1], 0, 2);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribIFormat(vao, 1, 1, GL_UNSIGNED_SHORT, 0);
  for (GLuint a : {0u, 1u}) {
    glVertexArrayAttribBinding(vao, a, a);
    glEnableVertexArrayAttrib(vao, a);
  }
  glVertexArrayElementBuffer(vao, buf[2]);
  return vao;
}

// A colour and depth framebuffer of `samples` (0: single-sampled).
GLuint make_fbo(int w, int h, int samples) {
  GLuint fbo = 0, rb[2] = {};
  glCreateFramebuffers(1, &fbo);
  glCreateRenderbuffers(2, rb);
  glNamedRenderbufferStorageMultisample(rb[0], samples, GL_RGBA8, w, h);
  glNamedRenderbufferStorageMultisample(rb[1], samples, GL_DEPTH_COMPONENT24, w, h);
  glNamedFramebufferRenderbuffer(fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fail_system("framebuffer incomplete (" + std::to_string(w) + "x" + std::to_string(h) + ", " +
                std::to_string(samples) + " samples)");
  return fbo;
}

// Near and far planes around the mesh's bounding sphere as seen from the eye.
glm::mat4 view_proj(const Options& o, const Mesh& m) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i < m.xyz.size(); i += 3) {
    const glm::vec3 p(m.xyz[i], m.xyz[i + 1], m.xyz[i + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float radius = 0.5f * glm::length(hi - lo) + 1e-4f;
  const float dist = glm::length(0.5f * (lo + hi) - o.cam.position);
  const float far_plane = dist + radius * 1.01f;
  const float near_plane = std::max(far_plane * 1e-4f, dist - radius * 1.01f);
  const glm::mat4 proj = glm::perspective(glm::radians(o.cam.fov_deg), float(o.width) / float(o.height), near_plane, far_plane);
  return proj * glm::lookAt(o.cam.position, o.cam.target, o.cam.up);
}

constexpr float kBackground = 0.92f;  // display value, written as is

ms::Image draw(const Options& o, const Mesh& m) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const GLuint msaa = make_fbo(o.width, o.height, std::min(4, max_samples));
  const GLuint resolved = make_fbo(o.width, o.height, 0);
  const GLuint prog = make_program();
  const GLuint vao = upload(m);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa);
  glViewport(0, 0, o.width, o.height);
  glClearColor(kBackground, kBackground, kBackground, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(prog);
  glUniformMatrix4fv(glGetUniformLocation(prog, "view_proj"), 1, GL_FALSE, glm::value_ptr(view_proj(o, m)));
  // The key light: above, left of and behind the camera.
  const glm::vec3 fwd = glm::normalize(o.cam.target - o.cam.position);
  const glm::vec3 right = glm::normalize(glm::cross(fwd, o.cam.up));
  const glm::vec3 up = glm::cross(right, fwd);
  const glm::vec3 key = glm::normalize(-0.45f * right + 0.7f * up - 0.55f * fwd);
  glUniform3fv(glGetUniformLocation(prog, "key_dir"), 1, glm::value_ptr(key));
  glUniform1i(glGetUniformLocation(prog, "wire"), o.wire ? 1 : 0);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m.index.size()), GL_UNSIGNED_INT, nullptr);
  glBlitNamedFramebuffer(msaa, resolved, 0, 0, o.width, o.height, 0, 0, o.width, o.height, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(o.width) * o.height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, o.width, o.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  if (glGetError() != GL_NO_ERROR) fail_system("GL error while drawing the mesh");
  ms::Image img{o.width, o.height, {"R", "G", "B"}, {}};
  img.pixels.resize(static_cast<std::size_t>(o.width) * o.height * 3);
  for (int y = 0; y < o.height; ++y)  // GL's rows are bottom first
    for (int x = 0; x < o.width; ++x)
      for (int c = 0; c < 3; ++c)
        img.pixels[(static_cast<std::size_t>(y) * o.width + x) * 3 + c] =
            rgba[(static_cast<std::size_t>(o.height - 1 - y) * o.width + x) * 4 + c] / 255.0f;
  return img;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_args(argc, argv);
    ms::check_output_path(o.out);
    const Mesh mesh = read_ply(o.mesh);
    auto ctx = ms::create_headless_context(ms::Backend::automatic);
    ms::write_image(draw(o, mesh), o.out, {{"Software", "marchstudio mesh-shot"}});
    std::fprintf(stderr, "mesh-shot: %zu triangles -> %s (%dx%d, %s)\n", mesh.index.size() / 3, o.out.c_str(),
                 o.width, o.height, ctx->info().renderer.c_str());
    return 0;
  } catch (const ms::Error& e) {
    std::fprintf(stderr, "mesh-shot: %s\n", ms::format_error(e.info()).c_str());
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mesh-shot: %s\n", e.what());
    return 2;
  }
}
