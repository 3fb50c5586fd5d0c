#include "io/cache_dir.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// $TMPDIR/marchstudio-<uid>, made 0700; empty unless it is ours alone. In a
// shared temporary directory anyone may have made that name first (a link
// elsewhere, a directory they can write): then there is no cache.
fs::path private_temp_dir() {
  std::error_code ec;
  const fs::path tmp = fs::temp_directory_path(ec);
  if (ec || tmp.empty()) return {};
  const uid_t uid = ::geteuid();
  const fs::path dir = tmp / ("marchstudio-" + std::to_string(uid));
  if (::mkdir(dir.c_str(), 0700) == 0) ::chmod(dir.c_str(), 0700);  // whatever the umask
  else if (errno != EEXIST) return {};
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != uid || (st.st_mode & 07777) != 0700)
    return {};
  return dir;
}

}  // namespace

fs::path cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg) return fs::path(xdg) / "marchstudio";
  if (home && *home) return fs::path(home) / ".cache" / "marchstudio";
  return private_temp_dir();
}

bool read_cache_file(const fs::path& path, std::string& bytes, std::size_t limit, std::string* why) {
  bytes.clear();
  std::string problem;
  const auto miss = [&](std::string text) {
    if (why) *why = std::move(text);
    bytes.clear();
    return false;
  };
  if (path.empty()) return miss({});
  const int fd = open_regular_file(path, problem, false);
  if (fd < 0) return miss(problem == "not found" ? std::string() : problem);
  struct stat st {};
  bool ok = ::fstat(fd, &st) == 0 && static_cast<std::uint64_t>(st.st_size) <= limit;
  if (!ok) problem = "is larger than the " + std::to_string(limit) + " bytes an entry may be";
  while (ok) {
    char buf[1 << 16];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ok = n == 0;
      if (!ok) problem = std::string("cannot be read: ") + std::strerror(errno);
      break;
    }
    bytes.append(buf, static_cast<std::size_t>(n));
    ok = bytes.size() <= limit;  // it grew since the fstat
    if (!ok) problem = "grew while it was read";
  }
  ::close(fd);
  if (!ok) return miss(problem);
  if (why) why->clear();
  return true;
}

bool write_cache_file(const fs::path& path, std::string_view bytes, std::string* why) {
  const auto no = [&](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  if (path.empty() || path.parent_path().empty()) return no("no cache directory");
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  // Never written through: a FIFO would block, a device or a link is not ours to replace.
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return no(path.string() + " is not a regular file");
  try {
    write_file_atomic(path, bytes);
  } catch (const Error& e) {
    return no(e.info().what);
  }
  return true;
}

}  // namespace ms
