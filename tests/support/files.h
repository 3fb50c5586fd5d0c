// Temporary directories and whole-file I/O for unit and CLI tests alike.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace ms::test {

// A fresh empty directory under the system temp dir, removed by the destructor.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of every entry, for "nothing was left behind" assertions.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

std::filesystem::path source_dir();  // the repository root
// Creates the parent directories first.
void write_file(const std::filesystem::path& p, const std::string& text);
// The whole file, bytes as stored; "" when it cannot be read.
std::string read_file(const std::filesystem::path& p);
// How many times `needle` occurs in `text` (overlaps counted): lines of output, say.
int count_of(const std::string& text, const std::string& needle);

}  // namespace ms::test
