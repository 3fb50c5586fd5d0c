// mesh/mesh.h's write_mesh(): a tetrahedron with two materials, written as
// OBJ, PLY, STL and GLB and read back here by hand (and the GLB by
// tinygltf's loader too): the counts, every position bit for bit, the
// material of each triangle, STL's normals outward. And the atomic rule: a
// write that fails throws Exit::system naming the file and leaves nothing.
#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <functional>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "files.h"
#include "mesh/mesh.h"

namespace ms {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

// Counter-clockwise seen from outside; the one material-1 triangle comes
// first so that grouping by material has something to do. Positions that
// are not short decimals: they must read back exactly all the same.
TriMesh tetrahedron() {
  TriMesh m;
  const glm::vec3 shift(1.0f / 3.0f, -2.7f, 1e-7f);
  for (const glm::vec3& p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)})
    m.positions.push_back(p * 0.1f + shift);
  m.material = {0, 1, 0, 1};
  m.indices = {1, 2, 3, 0, 2, 1, 0, 1, 3, 0, 3, 2};
  return m;
}

std::vector<MeshMaterial> materials() { return {{"red paint", {1.0f, 0.0f, 0.0f}}, {"blue", {0.0f, 0.0f, 1.0f}}}; }

template <class T>
T get(const std::string& bytes, std::size_t at) {
  T v;
  EXPECT_LE(at + sizeof v, bytes.size());
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

TEST(MeshWriters, ObjGroupsByMaterialWithAMtlBeside) {
  TempDir dir;
  const TriMesh m = tetrahedron();
  write_mesh(m, materials(), dir / "tet.obj");
  std::istringstream obj(test::read_file(dir / "tet.obj"));
  std::vector<glm::vec3> v;
  std::map<std::string, std::vector<std::vector<int>>> faces;
  std::string line, current, mtllib;
  while (std::getline(obj, line)) {
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    if (tag == "v") {
      std::string x, y, z;
      in >> x >> y >> z;
      v.emplace_back(std::strtof(x.c_str(), nullptr), std::strtof(y.c_str(), nullptr), std::strtof(z.c_str(), nullptr));
    } else if (tag == "usemtl") in >> current;
    else if (tag == "mtllib") in >> mtllib;
    else if (tag == "f") {
      int a, b, c;
      in >> a >> b >> c;
      faces[current].push_back({a, b, c});
    }
  }
  EXPECT_EQ(mtllib, "tet.mtl");
  ASSERT_EQ(v.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(v[i], m.positions[i]) << i;
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces["red_paint"].size(), 3u);
  EXPECT_EQ(faces["blue"], (std::vector<std::vector<int>>{{2, 3, 4}}));  // 1-based
  const std::string mtl = test::read_file(dir / "tet.mtl");
  EXPECT_NE(mtl.find("newmtl red_paint\nKd 1 0 0\nKa 0 0 0\nKs 0 0 0\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl blue\nKd 0 0 1\n"), std::string::npos) << mtl;
  EXPECT_EQ(dir.entries().size(), 2u);
}

TEST(MeshWriters, PlyIsBinaryLittleEndianWithAMaterialProperty) {
  TempDir dir;
  const TriMesh m = tetrahedron();
  write_mesh(m, materials(), dir / "tet.PLY");
  const std::string b = test::read_file(dir / "tet.PLY");
  const std::string end = "end_header\n";
  const std::size_t body = b.find(end) + end.size();
  const std::string header = b.substr(0, body);
  EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\ncomment marchstudio", 0), 0u) << header;
  EXPECT_NE(header.find("element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                        "property ushort material\nelement face 4\nproperty list uchar uint vertex_indices\n"),
            std::string::npos)
      << header;
  ASSERT_EQ(b.size(), body + 4 * 14 + 4 * 13);
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t at = body + 14 * i;
    EXPECT_EQ(glm::vec3(get<float>(b, at), get<float>(b, at + 4), get<float>(b, at + 8)), m.positions[i]);
    EXPECT_EQ(get<std::uint16_t>(b, at + 12), m.material[i]);
  }
  for (std::size_t t = 0; t < 4; ++t) {
    const std::size_t at = body + 56 + 13 * t;
    EXPECT_EQ(get<std::uint8_t>(b, at), 3);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(get<std::uint32_t>(b, at + 1 + 4 * c), m.indices[3 * t + c]);
  }
}

TEST(MeshWriters, StlNormalsPointOut) {
  TempDir dir;
  const TriMesh m = tetrahedron();
  write_mesh(m, materials(), dir / "tet.stl");
  const std::string b = test::read_file(dir / "tet.stl");
  ASSERT_EQ(b.size(), 84u + 4 * 50);
  EXPECT_EQ(b.rfind("marchstudio", 0), 0u);
  EXPECT_EQ(get<std::uint32_t>(b, 80), 4u);
  const glm::vec3 centre = (m.positions[0] + m.positions[1] + m.positions[2] + m.positions[3]) / 4.0f;
  for (std::size_t t = 0; t < 4; ++t) {
    const std::size_t at = 84 + 50 * t;
    const glm::vec3 n(get<float>(b, at), get<float>(b, at + 4), get<float>(b, at + 8));
    glm::vec3 face(0.0f);
    for (int c = 0; c < 3; ++c) {
      const std::size_t p = at + 12 + 12 * c;
      const glm::vec3 v(get<float>(b, p), get<float>(b, p + 4), get<float>(b, p + 8));
      EXPECT_EQ(v, m.positions[m.indices[3 * t + c]]);
      face += v / 3.0f;
    }
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    EXPECT_GT(glm::dot(n, face - centre), 0.0f) << "triangle " << t << " faces in";
    EXPECT_EQ(get<std::uint16_t>(b, at + 48), 0);
  }
}

TEST(MeshWriters, GlbHasAPrimitivePerMaterial) {
  TempDir dir;
  const TriMesh m = tetrahedron();
  write_mesh(m, materials(), dir / "tet.glb");
  const std::string b = test::read_file(dir / "tet.glb");
  ASSERT_GE(b.size(), 20u);
  EXPECT_EQ(b.substr(0, 4), "glTF");
  EXPECT_EQ(get<std::uint32_t>(b, 4), 2u);
  EXPECT_EQ(get<std::uint32_t>(b, 8), b.size());
  const std::uint32_t json_len = get<std::uint32_t>(b, 12);
  EXPECT_EQ(b.substr(16, 4), "JSON");
  EXPECT_EQ(json_len % 4, 0u);
  const nlohmann::json doc = nlohmann::json::parse(b.substr(20, json_len));
  const std::size_t bin = 20 + json_len;
  EXPECT_EQ(b.substr(bin + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(get<std::uint32_t>(b, bin), doc["buffers"][0]["byteLength"].get<std::uint32_t>());
  ASSERT_EQ(doc["materials"].size(), 2u);
  EXPECT_EQ(doc["materials"][1]["name"], "blue");
  EXPECT_EQ(doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"], nlohmann::json({1.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"], 0.0);
  const nlohmann::json& prims = doc["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 2u);
  ASSERT_EQ(doc["accessors"].size(), 4u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(prims[i]["attributes"], nlohmann::json({{"POSITION", 0}, {"_MATERIAL", 1}}));
    EXPECT_EQ(prims[i]["material"], i);
  }
  EXPECT_EQ(doc["accessors"][prims[0]["indices"].get<int>()]["count"], 9);  // red: three triangles
  EXPECT_EQ(doc["accessors"][prims[1]["indices"].get<int>()]["count"], 3);
  EXPECT_EQ(doc["accessors"][0]["count"], 4);
  EXPECT_EQ(doc["accessors"][0]["min"].size(), 3u);
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t at = bin + 8 + 12 * i;
    EXPECT_EQ(glm::vec3(get<float>(b, at), get<float>(b, at + 4), get<float>(b, at + 8)), m.positions[i]);
    EXPECT_EQ(get<float>(b, bin + 8 + 48 + 4 * i), float(m.material[i]));
  }

  // An independent reader accepts it, and sees the same structure.
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(b.data()),
                                          static_cast<unsigned>(b.size())))
      << err;
  EXPECT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].primitives.size(), 2u);
  EXPECT_EQ(model.materials.size(), 2u);
}

TEST(MeshWriters, AnEmptyMeshIsAValidFileOfEachFormat) {
  TempDir dir;
  for (const char* name : {"e.obj", "e.ply", "e.stl", "e.glb"}) {
    write_mesh(TriMesh{}, {}, dir / name);
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  }
  const std::string glb = test::read_file(dir / "e.glb");
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned>(glb.size())))
      << err;
}

Exit code_of(const std::function<void()>& f, std::string* what = nullptr) {
  try {
    f();
  } catch (const Error& e) {
    if (what) *what = format_error(e.info());
    return e.code();
  }
  return Exit::ok;
}

TEST(MeshWriters, BadInputIsRefusedBeforeAnyFile) {
  TempDir dir;
  TriMesh bad = tetrahedron();
  EXPECT_EQ(code_of([&] { write_mesh(tetrahedron(), materials(), dir / "tet.vdb"); }), Exit::bad_input);
  EXPECT_EQ(code_of([&] { write_mesh(tetrahedron(), materials(), dir / "tet.txt"); }), Exit::bad_input);
  bad.indices.push_back(0);
  EXPECT_EQ(code_of([&] { write_mesh(bad, materials(), dir / "tet.ply"); }), Exit::bad_input);
  bad.indices = {0, 1, 4};
  EXPECT_EQ(code_of([&] { write_mesh(bad, materials(), dir / "tet.stl"); }), Exit::bad_input);
  bad = tetrahedron();
  bad.material.pop_back();
  EXPECT_EQ(code_of([&] { write_mesh(bad, materials(), dir / "tet.glb"); }), Exit::bad_input);
  EXPECT_TRUE(dir.entries().empty());
}

// A link to /dev/full: AtomicFile writes a character device in place, and
// every write there fails (ENOSPC), even for root. For OBJ the .mtl is
// written first, then removed when the .obj fails.
TEST(MeshWriters, AFullDeviceIsASystemErrorAndLeavesNothing) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (const char* name : {"m.obj", "m.ply", "m.stl", "m.glb"}) {
    TempDir dir;
    fs::create_symlink("/dev/full", dir / name);
    std::string what;
    EXPECT_EQ(code_of([&] { write_mesh(tetrahedron(), materials(), dir / name); }, &what), Exit::system) << name;
    EXPECT_NE(what.find(name), std::string::npos) << what;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
  }
}

TEST(MeshWriters, ADirectoryThatCannotBeMadeIsASystemErrorAndLeavesNothing) {
  for (const char* name : {"m.obj", "m.ply", "m.stl", "m.glb"}) {
    TempDir dir;
    test::write_file(dir / "file", "x");  // a directory that cannot be made: a file is in the way
    EXPECT_EQ(code_of([&] { write_mesh(tetrahedron(), materials(), dir / "file" / name); }), Exit::system) << name;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});
  }
}

// Root ignores a directory's permissions, so as root the writes run in a
// child that has become nobody (65534) first.
TEST(MeshWriters, AReadOnlyDirectoryIsASystemErrorAndLeavesNothing) {
  TempDir dir;
  const fs::path ro = dir / "ro";
  fs::create_directory(ro);
  fs::permissions(dir.path(), fs::perms::owner_all | fs::perms::others_exec | fs::perms::group_exec);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::others_read |
                          fs::perms::others_exec | fs::perms::group_read | fs::perms::group_exec);
  const auto write_all = [&] {
    int failures = 0;
    for (const char* name : {"m.obj", "m.ply", "m.stl", "m.glb"})
      failures += code_of([&] { write_mesh(tetrahedron(), materials(), ro / name); }) != Exit::system;
    return failures;
  };
  if (::geteuid() != 0) {
    EXPECT_EQ(write_all(), 0);
  } else {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      if (::setresgid(65534, 65534, 65534) != 0 || ::setresuid(65534, 65534, 65534) != 0) std::_Exit(100);
      if (::access(ro.c_str(), R_OK | X_OK) != 0) std::_Exit(102);  // the failure must be the directory's mode
      std::_Exit(::access(ro.c_str(), W_OK) == 0 ? 101 : write_all());
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "100: could not become nobody; 101: nobody may write; 102: nor "
                                         "read; else: writes that did not fail with Exit::system";
  }
  fs::permissions(ro, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(ro));
}

}  // namespace
}  // namespace ms
