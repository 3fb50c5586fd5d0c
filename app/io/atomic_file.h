// Every file marchstudio writes goes through here: a temporary beside the
// target, every write checked, then fsync, a size check and a rename. The
// target appears only complete; a failure (a full disk, an I/O error)
// removes the temporary and throws Exit::system naming the target.
//
//   AtomicFile f("out/frame_0001.png");
//   f.write(bytes, n);     // a failure is recorded here, reported by commit()
//   f.commit();            // verified, renamed into place; throws ms::Error
//
//   write_file_atomic("sweep.csv", text);   // the same for a whole buffer
//
// Only a regular file (or a missing one) is replaced so. A character
// device or a FIFO (`--junit /dev/null`, a pipe to a reader) is written
// through instead: opened and written in place, never renamed over, so that
// /dev/null stays a device; a FIFO that no process reads is an error rather
// than a wait. Anything else (a directory, a socket) is refused, bad_input.
//
// Codecs write through AtomicFile (image_io.cpp's IOProxy) rather than to
// a path: OpenImageIO's PNG writer ignores failed writes, and libjpeg's
// default error handler calls exit(1). A proxy that records a failure and
// tells the codec all is well lets commit() decide, the same for every format.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ms {

// How `target` is written (see above). Throws bad_input naming `key` for
// a target that is neither: call it before the work, as for the directory.
enum class OutputKind { replace, through };
OutputKind output_kind(const std::filesystem::path& target, const std::string& key = {});

class AtomicFile {
 public:
  // Creates the temporary (temp_path_for(target, pid)), and the target's
  // directory first when missing; throws system when either cannot be made.
  // A device or FIFO target is opened instead (no temporary; temp() empty).
  explicit AtomicFile(std::filesystem::path target, bool keep_extension = false);
  ~AtomicFile();  // without commit(): the temporary is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Writes at the end, or at `offset`. Return false once anything failed.
  bool write(const void* data, std::size_t n);
  bool pwrite(const void* data, std::size_t n, std::uint64_t offset);
  // The bytes went to temp() by its name, from a writer that must reread
  // what it wrote (libtiff, through OpenImageIO): the size on disk becomes
  // the size written. That writer must have checked its own writes. (A
  // target written through has no temp(): such a writer cannot write it.)
  void written_by_name();
  bool failed() const { return error_ != 0; }
  std::uint64_t size() const { return size_; }
  const std::filesystem::path& temp() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }

  // fsync, the size on disk against the bytes written, close, rename, and
  // fsync of the directory (written through: the close alone). Throws
  // system naming the target.
  void commit();
  // Closes and removes the temporary now (for a writer that gave up); a
  // target written through is closed, never removed.
  void discard();
  // The permissions the file gets (else 0666 less the umask); nothing for
  // a target written through (a device's are not ours to change).
  void set_mode(unsigned mode);

 private:
  void open_through();

  std::filesystem::path target_, temp_;
  int fd_ = -1;
  int error_ = 0;           // the first errno that failed, 0 while all is well
  std::uint64_t pos_ = 0;   // where write() appends
  std::uint64_t size_ = 0;  // the furthest byte written
  bool through_ = false;    // a device or FIFO, written in place
  std::uint64_t stream_ = 0;  // written through: where the next write() lands
};

// A whole buffer; `mode` >= 0: the file's permissions (else 0666 less the umask).
void write_file_atomic(const std::filesystem::path& target, std::string_view bytes, int mode = -1);

// A report or list named by a flag (`key`): the path checked as an image
// output is (a file name, a directory that is or can be made), then
// write_file_atomic(). Throws bad_input for the path, system for the write.
void write_text_file(const std::filesystem::path& path, std::string_view text, const std::string& key = "-o");

// The temporary of `target` for process `pid`: ".<name>.tmp<pid>" beside
// it, or with keep_extension ".<stem>.tmp<pid><ext>" (for ffmpeg, which
// picks a container by the extension). Shortened, with a hash of the whole
// name, so that it stays within the file system's name limit.
std::filesystem::path temp_path_for(const std::filesystem::path& target, long pid, bool keep_extension = false);

// Whether `name` (a file name) is a temporary of `target` by any process.
bool is_temp_of(std::string_view name, const std::filesystem::path& target);

// Check before any work that files can be written in `dir`: a writable
// directory, or one that can be made (mkdir -p) under the nearest existing
// one; AtomicFile makes it. Throws bad_input naming `key`.
void check_output_directory(const std::filesystem::path& dir, const std::string& key);

// The file system's limit on one name in `dir` (NAME_MAX, usually 255).
std::size_t name_limit(const std::filesystem::path& dir);

}  // namespace ms
