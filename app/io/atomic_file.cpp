#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

#include "core/error.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// FNV-1a: a short, stable tag for a shortened name.
std::string hash8(std::string_view s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%08llx", static_cast<unsigned long long>(h & 0xffffffffull));
  return buf;
}

// The part of the temporary's name before the pid: ".<name>.tmp" (or
// ".<stem>.tmp" with the extension after the pid), the name cut and tagged
// with its hash when the whole would not fit in `limit` bytes.
std::string temp_prefix(const fs::path& target, bool keep_extension, std::size_t limit) {
  const std::string name = target.filename().string();
  const std::string ext = keep_extension ? target.extension().string() : "";
  std::string base = keep_extension ? target.stem().string() : name;
  constexpr std::size_t kPid = 10;  // digits a pid may take
  const std::size_t room = limit > 1 + 4 + kPid + ext.size() ? limit - 1 - 4 - kPid - ext.size() : 0;
  if (base.size() > room) {
    const std::string tag = "~" + hash8(name);
    base = base.substr(0, room > tag.size() ? room - tag.size() : 0) + tag;
  }
  return "." + base + ".tmp";
}

std::string system_message(int err) { return std::strerror(err); }

}  // namespace

std::size_t name_limit(const fs::path& dir) {
  const long n = ::pathconf(dir.empty() ? "." : dir.c_str(), _PC_NAME_MAX);
  return n > 0 ? static_cast<std::size_t>(n) : NAME_MAX;
}

fs::path temp_path_for(const fs::path& target, long pid, bool keep_extension) {
  const std::string ext = keep_extension ? target.extension().string() : "";
  return target.parent_path() /
         (temp_prefix(target, keep_extension, name_limit(target.parent_path())) + std::to_string(pid) + ext);
}

bool is_temp_of(std::string_view name, const fs::path& target) {
  for (const bool keep : {false, true}) {
    const std::string prefix = temp_prefix(target, keep, name_limit(target.parent_path()));
    const std::string ext = keep ? target.extension().string() : "";
    if (name.size() <= prefix.size() + ext.size() || name.substr(0, prefix.size()) != prefix) continue;
    if (name.substr(name.size() - ext.size()) != ext) continue;
    const std::string_view pid = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
    if (!pid.empty() && pid.find_first_not_of("0123456789") == std::string_view::npos) return true;
  }
  return false;
}

void check_output_directory(const fs::path& dir, const std::string& key) {
  std::error_code ec;
  fs::path existing = dir;
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, ec))
    fail_input(existing == dir ? "output directory is not a directory"
                               : "output directory cannot be made: " + existing.string() + " is not a directory",
               dir.string(), 0, key);
  if (::access(existing.c_str(), W_OK) != 0)
    fail_input(existing == dir ? "output directory is not writable"
                               : "output directory cannot be made: " + existing.string() + " is not writable",
               dir.string(), 0, key);
}

OutputKind output_kind(const fs::path& target, const std::string& key) {
  struct stat st {};
  // Missing (or a link to nothing): made anew. Other stat errors show when it is opened.
  if (::stat(target.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return OutputKind::replace;
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return OutputKind::through;
  const char* what = S_ISDIR(st.st_mode)    ? "a directory"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                     : S_ISBLK(st.st_mode)  ? "a block device"
                                            : "not a regular file";
  fail_input(std::string("output path is ") + what, target.string(), 0, key,
             "a regular file is replaced; a FIFO or a character device is written to; nothing else");
}

AtomicFile::AtomicFile(fs::path target, bool keep_extension) : target_(std::move(target)) {
  if (output_kind(target_) == OutputKind::through) {
    open_through();
    return;
  }
  temp_ = temp_path_for(target_, ::getpid(), keep_extension);
  std::error_code ec;
  if (!target_.parent_path().empty() && !fs::is_directory(target_.parent_path(), ec) &&
      !fs::create_directories(target_.parent_path(), ec) && ec)
    fail_system("cannot make the output directory: " + ec.message(), target_.parent_path().string());
  // O_EXCL: a name someone else made is never written through.
  fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0 && errno == EEXIST) {  // a stale one of this pid (a reused pid): ours to replace
    ::unlink(temp_.c_str());
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  }
  if (fd_ < 0) fail_system("cannot create a temporary file: " + system_message(errno), target_.string());
}

void AtomicFile::open_through() {
  through_ = true;
  // O_NONBLOCK for the open alone: a FIFO that no process reads fails
  // (ENXIO) rather than waiting for a reader that may never come.
  fd_ = ::open(target_.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd_ < 0)
    fail_system(errno == ENXIO ? "cannot write to the FIFO: no process is reading it"
                               : "cannot open the file: " + system_message(errno),
                target_.string());
  struct stat st {};
  const int flags = ::fcntl(fd_, F_GETFL);
  if (::fstat(fd_, &st) != 0 || !(S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) || flags < 0 ||
      ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK) != 0) {
    ::close(fd_);  // replaced by another kind of file since it was looked at
    fd_ = -1;
    fail_system("cannot write the file: it changed while it was opened", target_.string());
  }
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
    if (!through_) ::unlink(temp_.c_str());
  }
}

void AtomicFile::written_by_name() {
  struct stat st {};
  if (fd_ < 0 || error_ || through_) return;
  if (::fstat(fd_, &st) != 0) error_ = errno;
  else size_ = static_cast<std::uint64_t>(st.st_size);
}

bool AtomicFile::pwrite(const void* data, std::size_t n, std::uint64_t offset) {
  if (error_ || fd_ < 0) return false;
  const char* p = static_cast<const char*>(data);
  std::size_t done = 0;
  while (done < n) {
    // Written through, a FIFO cannot seek: bytes that follow the last ones are appended.
    const bool append = through_ && offset + done == stream_;
    const ssize_t w = append ? ::write(fd_, p + done, n - done)
                             : ::pwrite(fd_, p + done, n - done, static_cast<off_t>(offset + done));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error_ = w < 0 ? errno : ENOSPC;  // a write of 0 bytes: the disk is full
      return false;
    }
    if (append) stream_ += static_cast<std::uint64_t>(w);
    done += static_cast<std::size_t>(w);
  }
  if (offset + n > size_) size_ = offset + n;
  return true;
}

bool AtomicFile::write(const void* data, std::size_t n) {
  if (!pwrite(data, n, pos_)) return false;
  pos_ += n;
  return true;
}

void AtomicFile::commit() {
  if (fd_ < 0) fail_system("internal: commit of a closed file", target_.string());
  if (through_) {  // a device or FIFO: no size to check, nothing to rename
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && !error_) error_ = errno;
    if (error_) fail_system("cannot write the file: " + system_message(error_), target_.string());
    return;
  }
  // Delayed allocation: a full disk may only show at fsync or close.
  if (!error_ && ::fsync(fd_) != 0) error_ = errno;
  struct stat st {};
  if (!error_ && ::fstat(fd_, &st) != 0) error_ = errno;
  if (!error_ && static_cast<std::uint64_t>(st.st_size) != size_) error_ = EIO;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && !error_) error_ = errno;
  if (!error_ && ::rename(temp_.c_str(), target_.c_str()) != 0) error_ = errno;
  if (error_) {
    ::unlink(temp_.c_str());
    fail_system("cannot write the file: " + system_message(error_) + "; nothing was written", target_.string());
  }
  // The rename itself is durable only once the directory is.
  const fs::path dir = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

void AtomicFile::set_mode(unsigned mode) {
  if (fd_ >= 0 && !through_ && ::fchmod(fd_, static_cast<mode_t>(mode)) != 0 && !error_) error_ = errno;
}

void write_text_file(const fs::path& path, std::string_view text, const std::string& key) {
  if (path.filename().empty()) fail_input("output path names no file", path.string(), 0, key);
  // A device or FIFO is written in place: its directory (/dev) need not be writable.
  if (output_kind(path, key) == OutputKind::replace)
    check_output_directory(path.parent_path().empty() ? fs::path(".") : path.parent_path(), key);
  write_file_atomic(path, text);
}

void write_file_atomic(const fs::path& target, std::string_view bytes, int mode) {
  AtomicFile f(target);
  if (mode >= 0) f.set_mode(static_cast<unsigned>(mode));
  f.write(bytes.data(), bytes.size());
  f.commit();
}

}  // namespace ms
