// `render --jobs FILE` with mesh lines (cli/job_list.h): a line whose
// output is a mesh file, or that has a "mesh" object, is exported through
// the batch's session beside the stills; a bad mesh key fails its line
// alone, one line naming FILE:LINE and the key (its JSON pointer inside
// "mesh"), as every bad line of a batch does.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "io/image_io.h"
#include "run.h"

namespace ms::test {
namespace {

namespace fs = std::filesystem;

std::string seed() { return (source_dir() / "scenes" / "seed.toml").string(); }

// The vertex count of a binary PLY's header; 0 when it is not one.
long ply_vertices(const fs::path& file) {
  const std::string text = read_file(file);
  if (text.rfind("ply\n", 0) != 0) return 0;
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("element vertex (\\d+)\n"))) return 0;
  return std::stol(m[1].str());
}

TEST(BatchMesh, StillsAndMeshesAreWrittenInOneBatch) {
  TempDir dir;
  write_file(dir / "jobs.jsonl", "{\"scene\": \"" + seed() + "\", \"output\": \"a.png\"}\n" +
                                     "{\"scene\": \"" + seed() + "\", \"output\": \"b.ply\", \"resolution\": 32}\n" +
                                     "{\"scene\": \"" + seed() + "\", \"mesh\": {\"resolution\": 16}}\n");
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18", "-v"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image img = read_image(dir / "a.png");
  EXPECT_EQ(img.width, 32);
  const long coarse = ply_vertices(dir / "b.ply");
  EXPECT_GT(coarse, 100) << "b.ply is not the seed sphere's mesh";
  EXPECT_NE(read_file(dir / "seed.obj").find("\nv "), std::string::npos) << "a \"mesh\" line without output";
  EXPECT_TRUE(fs::exists(dir / "seed.mtl"));
  // Every file written, one a line: the OBJ line's .mtl too, as `mesh` prints.
  EXPECT_EQ(count_of(r.out, "\n"), 4) << r.out;
  EXPECT_NE(r.out.find("seed.mtl\n"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("marchstudio: batch: 1 images, 2 meshes, "), std::string::npos) << r.err;
}

TEST(BatchMesh, ABadMeshKeyFailsItsLineAlone) {
  TempDir dir;
  const std::string s = "\"scene\": \"" + seed() + "\"";
  write_file(dir / "jobs.jsonl", "{" + s + ", \"output\": \"a.png\"}\n" +                      // 1: good
                                     "{" + s + ", \"output\": \"x.ply\", \"resolution\": \"32\"}\n" +  // 2
                                     "{" + s + ", \"output\": \"y.ply\", \"mesh\": {\"bandd\": 3}}\n" +  // 3
                                     "{" + s + ", \"output\": \"z.stl\", \"size\": \"32x18\"}\n" +      // 4
                                     "{" + s + ", \"output\": \"w.png\", \"resolution\": 32}\n" +       // 5
                                     "{" + s + ", \"output\": \"v.ply\", \"bounds\": [0, 0, 1]}\n");   // 6
  const RunResult r = run_marchstudio({"render", "--jobs", "jobs.jsonl", "--size", "32x18"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:2: 'resolution' must be an integer "
                                                  "in 8\\.\\.4096[^\\n]*\\n")))
      << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:3: unknown key '/mesh/bandd' \\(did you "
                                                  "mean 'band'\\?\\)\\n")))
      << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:4: 'size' [^\\n]*mesh[^\\n]*\\n"))) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:5: 'resolution' is a mesh key[^\\n]*\\n")))
      << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("marchstudio: jobs\\.jsonl:6: 'bounds' must be[^\\n]*\\n"))) << r.err;
  EXPECT_NE(r.err.find("marchstudio: 5 of 6 jobs failed\n"), std::string::npos) << r.err;
  EXPECT_EQ(count_of(r.err, "\n"), 6) << "one line per bad job and the total: " << r.err;
  // Each bad line writes nothing; the good one is written.
  EXPECT_TRUE(fs::exists(dir / "a.png"));
  EXPECT_EQ(dir.entries().size(), 2u) << r.err;
}

}  // namespace
}  // namespace ms::test
