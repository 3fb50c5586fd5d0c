// A fault injector, preloaded into marchstudio by a test (LD_PRELOAD): each
// open() that creates one of its temporaries (io/atomic_file.h: a name
// ".<target>.tmp<pid>") returns only after SLOW_TEMP_MS milliseconds (300
// unless set). That holds the process in the window just after the
// temporary exists, where a signal once found no handler and left it
// behind (tests/cli/test_huge_still.cpp).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void hold_if_temp(const char* path, int flags) {
  if (!(flags & O_CREAT) || !path) return;
  const char* base = strrchr(path, '/');
  base = base ? base + 1 : path;
  if (base[0] != '.' || !strstr(base, ".tmp")) return;
  const char* ms = getenv("SLOW_TEMP_MS");
  usleep((useconds_t)(ms ? atoi(ms) : 300) * 1000u);
}

// The mode argument is there only with O_CREAT (or O_TMPFILE); reading it
// always is what glibc's own wrappers do.
#define MODE_ARG(flags) \
  va_list ap;           \
  va_start(ap, flags);  \
  int mode = va_arg(ap, int); \
  va_end(ap)

int open(const char* path, int flags, ...) {
  MODE_ARG(flags);
  int (*real)(const char*, int, ...) = (int (*)(const char*, int, ...))dlsym(RTLD_NEXT, "open");
  int fd = real(path, flags, mode);
  if (fd >= 0) hold_if_temp(path, flags);
  return fd;
}

int open64(const char* path, int flags, ...) {
  MODE_ARG(flags);
  int (*real)(const char*, int, ...) = (int (*)(const char*, int, ...))dlsym(RTLD_NEXT, "open64");
  int fd = real(path, flags, mode);
  if (fd >= 0) hold_if_temp(path, flags);
  return fd;
}

int openat(int dir, const char* path, int flags, ...) {
  MODE_ARG(flags);
  int (*real)(int, const char*, int, ...) = (int (*)(int, const char*, int, ...))dlsym(RTLD_NEXT, "openat");
  int fd = real(dir, path, flags, mode);
  if (fd >= 0) hold_if_temp(path, flags);
  return fd;
}
