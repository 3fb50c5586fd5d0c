#include "io/module_file.h"

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace ms {
namespace fs = std::filesystem;

namespace {

// Whether [offset, offset + count x size) lies within a file of `file_size` bytes.
bool within(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t file_size) {
  return offset <= file_size && (size == 0 || count <= (file_size - offset) / size);
}

// Why `fd` is not a whole shared object, or empty. dlopen maps the file and
// touches what its headers point to: past the end of a file cut short (a
// partial copy or install) that is SIGBUS, not an error.
std::string elf_problem(int fd, std::uint64_t file_size) {
  ElfW(Ehdr) eh{};
  if (::pread(fd, &eh, sizeof eh, 0) != static_cast<ssize_t>(sizeof eh) ||
      std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0)
    return "not a shared object (no ELF header)";
  if (eh.e_ident[EI_CLASS] != (sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32) || eh.e_phentsize != sizeof(ElfW(Phdr)))
    return "a shared object for another machine";
  const std::string cut = "cut short at " + std::to_string(file_size) + " bytes (a partial copy?): ";
  if (eh.e_shoff != 0 && !within(eh.e_shoff, eh.e_shnum, eh.e_shentsize, file_size))
    return cut + "its section table lies past the end";
  if (!within(eh.e_phoff, eh.e_phnum, eh.e_phentsize, file_size)) return cut + "its program headers lie past the end";
  for (int i = 0; i < eh.e_phnum; ++i) {
    ElfW(Phdr) ph{};
    if (::pread(fd, &ph, sizeof ph, static_cast<off_t>(eh.e_phoff + i * sizeof ph)) != static_cast<ssize_t>(sizeof ph))
      return cut + "its program headers cannot be read";
    if (ph.p_type == PT_LOAD && !within(ph.p_offset, 1, ph.p_filesz, file_size))
      return cut + "a segment lies past the end";
  }
  return {};
}

// Empty when `path` is a regular file holding a whole shared object. Opened
// O_NONBLOCK: a FIFO there would block dlopen's open for ever.
std::string module_problem(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  struct stat st {};
  std::string problem;
  if (::fstat(fd, &st) != 0) problem = std::strerror(errno);
  else if (!S_ISREG(st.st_mode)) problem = "not a regular file";
  else problem = elf_problem(fd, static_cast<std::uint64_t>(st.st_size));
  ::close(fd);
  return problem;
}

}  // namespace

// A build tree, or a copy made by hand, keeps the module beside the
// executable; `cmake --install` puts it in lib/marchstudio/, beside bin/.
fs::path module_path(const char* env, const char* file, const fs::path& build_dir) {
  if (const char* e = std::getenv(env); e && *e) return e;
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    const fs::path dir = fs::path(std::string(exe, static_cast<size_t>(n))).parent_path();
    for (const fs::path& p : {dir / file, dir / "../lib/marchstudio" / file}) {
      std::error_code ec;
      if (fs::exists(p, ec)) return p.lexically_normal();
    }
  }
  return build_dir / file;
}

void* open_module(const fs::path& path, std::string& error) {
  if (error = module_problem(path); !error.empty()) return nullptr;
  // RTLD_LOCAL: the module's dependencies never resolve our symbols or the GL's.
  void* lib = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* e = dlerror();
    error = e ? e : "dlopen failed";
  }
  return lib;
}

}  // namespace ms
