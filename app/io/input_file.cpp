#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

std::string kind_problem(mode_t mode) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return "is a directory, not a regular file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

std::string errno_problem(int err) {
  if (err == ENOENT || err == ENOTDIR) return "not found";
  if (err == EACCES || err == EPERM) return "is not readable (permission denied)";
  if (err == ELOOP) return "is a symlink loop";
  if (err == ENAMETOOLONG) return "has a name too long for the file system";
  return std::string("cannot be opened: ") + std::strerror(err);
}

[[noreturn]] void refuse(const fs::path& path, std::string_view what, std::string_view key, const std::string& why) {
  fail_input(std::string(what) + " " + why, path.string(), 0, std::string(key));
}

}  // namespace

int open_regular_file(const fs::path& path, std::string& why, bool follow_links) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | (follow_links ? 0 : O_NOFOLLOW));
  if (fd < 0) {
    why = !follow_links && errno == ELOOP ? "is a symbolic link, not followed" : errno_problem(errno);
    return -1;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    why = errno_problem(errno);
  } else {
    why = kind_problem(st.st_mode);
  }
  if (!why.empty()) {
    ::close(fd);
    return -1;
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return fd;
}

std::string input_file_problem(const fs::path& path) {
  if (path.empty()) return "not found (empty path)";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return errno_problem(errno);
  if (std::string k = kind_problem(st.st_mode); !k.empty()) return k;
  if (::access(path.c_str(), R_OK) != 0) return errno_problem(errno);
  return {};
}

void check_input_file(const fs::path& path, std::string_view what, std::string_view key) {
  if (std::string why = input_file_problem(path); !why.empty()) refuse(path, what, key, why);
}

std::string read_input_file(const fs::path& path, std::string_view what, std::string_view key, std::size_t max_bytes) {
  std::string why;
  if (path.empty()) refuse(path, what, key, "not found (empty path)");
  const int fd = open_regular_file(path, why);
  if (fd < 0) refuse(path, what, key, why);
  struct stat st {};
  ::fstat(fd, &st);
  if (static_cast<std::size_t>(st.st_size) > max_bytes) {
    ::close(fd);
    refuse(path, what, key,
           "is " + std::to_string(st.st_size >> 20) + " MiB, more than the " + std::to_string(max_bytes >> 20) +
               " MiB marchstudio reads");
  }
  std::string out(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  // A file that grows while read is read as far as it was; one that shrinks ends early.
  while (done < out.size()) {
    const ssize_t n = ::read(fd, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      fail_system(std::string("cannot read ") + std::string(what) + ": " + std::strerror(err), path.string());
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  out.resize(done);
  ::close(fd);
  return out;
}

}  // namespace ms
