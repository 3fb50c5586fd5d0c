// A copy of sdf_shaders/ under `dir` whose main() makes the left 8 columns'
// sample colour NaN, as a broken user map() or material would: the flag
// path of main.frag and post.frag (the NaN guard) through the real binary.
// A test failure when main.frag no longer has the line it hooks into.
//
//   const fs::path shaders = nan_injecting_shader_dir(dir.path());
//   ASSERT_FALSE(HasFailure());
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run.h"

namespace ms::test {

inline std::filesystem::path nan_injecting_shader_dir(const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "shaders";
  std::filesystem::copy(source_dir() / "sdf_shaders", out, std::filesystem::copy_options::recursive);
  std::string frag = read_file(out / "main.frag");
  const size_t at = frag.find("  bool nonFinite = notFinite(c);");
  EXPECT_NE(at, std::string::npos) << "main.frag changed: update tests/cli/nan_shaders.h";
  if (at != std::string::npos)
    frag.insert(at, "  if (gl_FragCoord.x < 8.0) c = vec3(uintBitsToFloat(0x7fc00000u));\n");
  write_file(out / "main.frag", frag);
  return out;
}

}  // namespace ms::test
