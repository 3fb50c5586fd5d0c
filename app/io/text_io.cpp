#include "io/text_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

bool write_all(int fd, const std::string& text) {
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// The bytes on disk are the bytes we meant: a short write that reported
// success (a full network disk) must not be renamed over a good file.
bool reads_back(const std::string& tmp, const std::string& text) {
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::string back;
  char buf[65536];
  ssize_t n;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) back.append(buf, static_cast<size_t>(n));
  ::close(fd);
  return n == 0 && back == text;
}

}  // namespace

void write_text_file(const fs::path& path, const std::string& text, const std::string& key) {
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (path.filename().empty()) fail_input("output path names no file", path.string(), 0, key);
  if (!fs::is_directory(dir, ec)) fail_input("output directory does not exist", dir.string(), 0, key);
  if (::access(dir.c_str(), W_OK) != 0) fail_input("output directory is not writable", dir.string(), 0, key);
  if (fs::is_directory(path, ec)) fail_input("output path is a directory", path.string(), 0, key);

  // Appended rather than "." + name: GCC 12 warns falsely (-Wrestrict) on that.
  std::string name(1, '.');
  name.append(path.filename().string()).append(".XXXXXX");
  std::string tmp = (dir / name).string();
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) fail_system("cannot create a temporary file: " + std::string(std::strerror(errno)), path.string());
  std::string why;
  auto step = [&why](bool ok, const char* what) {
    if (!ok && why.empty()) why = std::string(what) + ": " + std::strerror(errno ? errno : EIO);
  };
  step(::fchmod(fd, 0644) == 0, "chmod");
  step(write_all(fd, text), "write");
  step(::fsync(fd) == 0, "fsync");
  step(::close(fd) == 0, "close");
  if (why.empty() && !reads_back(tmp, text)) why = "the file read back differs from what was written";
  if (why.empty()) step(::rename(tmp.c_str(), path.c_str()) == 0, "rename");
  if (!why.empty()) {
    ::unlink(tmp.c_str());
    fail_system("cannot write file (" + why + ")", path.string());
  }
}

}  // namespace ms
