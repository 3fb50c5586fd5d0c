// Helpers shared by the test_shader_*.cpp files: test data paths, a #line
// interpreter, and running glslangValidator when it is installed.
#pragma once
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"  // TempDir, read_file

namespace ms::test {

inline std::filesystem::path shader_data(const std::string& rel = {}) {
  std::filesystem::path p = std::filesystem::path(MARCH_TEST_DATA) / "shader";
  return rel.empty() ? p : p / rel;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string l; std::getline(ss, l);) out.push_back(l);
  return out;
}

// 1-based number of the first line containing `needle`, 0 if none.
inline int line_containing(const std::string& text, const std::string& needle) {
  std::vector<std::string> ls = lines_of(text);
  for (size_t i = 0; i < ls.size(); ++i)
    if (ls[i].find(needle) != std::string::npos) return static_cast<int>(i) + 1;
  return 0;
}

// Where a GLSL >= 3.30 compiler thinks assembled line n (1-based) is:
// `#line L S` makes the NEXT line line L of string S. Independent of the
// preprocessor under test; it ignores #if groups.
struct Where { int string_no = -1; int line = 0; };
inline Where compiler_location(const std::string& text, int n) {
  int s = 0, l = 1;
  std::vector<std::string> ls = lines_of(text);
  for (int i = 1; i <= static_cast<int>(ls.size()); ++i) {
    int nl = 0, ns = 0;
    if (std::sscanf(ls[i - 1].c_str(), " #line %d %d", &nl, &ns) == 2) {
      if (i == n) return {};
      l = nl;
      s = ns;
      continue;
    }
    if (i == n) return {s, l};
    ++l;
  }
  return {};
}

inline bool have_glslang() { return std::system("command -v glslangValidator >/dev/null 2>&1") == 0; }

struct GlslangResult { int status = -1; std::string output; };

// Compiles `text` as a fragment shader with glslangValidator.
inline GlslangResult run_glslang(const std::string& text, const std::string& tag) {
  const TempDir dir;
  const std::filesystem::path f = dir / (tag + ".frag");
  { std::ofstream(f, std::ios::binary) << text; }
  GlslangResult r;
  std::string cmd = "glslangValidator -S frag '" + f.string() + "' 2>&1";
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
    r.status = ::pclose(p);
  }
  return r;
}

}  // namespace ms::test
