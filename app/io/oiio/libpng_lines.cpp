// LibpngLines (oiio.h): fd 2 goes to a memory file while a decode runs, and
// what came meanwhile goes on to the real stderr without libpng's lines.
#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <string>

#include "io/oiio/oiio.h"

namespace ms::oiio {

namespace {

// One capture for the process, however many threads decode at once: the
// last scope to end puts fd 2 back.
std::mutex g_mutex;
int g_depth = 0;
int g_saved = -1;    // the real stderr, while captured
int g_capture = -1;  // the memory file fd 2 points at

void write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w <= 0) return;  // stderr gone: nothing else to tell it with
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

// Every line but libpng's own ("libpng error: ...", "libpng warning: ...").
void forward(int from, int to) {
  std::string text;
  char buf[4096];
  for (off_t at = 0;;) {
    const ssize_t r = ::pread(from, buf, sizeof buf, at);
    if (r <= 0) break;
    text.append(buf, static_cast<std::size_t>(r));
    at += r;
  }
  std::string kept;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t nl = text.find('\n', at);
    nl = nl == std::string::npos ? text.size() : nl + 1;
    if (text.compare(at, 7, "libpng ") != 0) kept.append(text, at, nl - at);
    at = nl;
  }
  write_all(to, kept.data(), kept.size());
}

}  // namespace

LibpngLines::LibpngLines() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_depth++ > 0) return;
  std::fflush(stderr);
  g_capture = ::memfd_create("marchstudio-stderr", MFD_CLOEXEC);
  g_saved = g_capture >= 0 ? ::fcntl(2, F_DUPFD_CLOEXEC, 3) : -1;
  if (g_saved < 0 || ::dup2(g_capture, 2) < 0) {  // no capture: libpng's lines show, nothing worse
    if (g_saved >= 0) ::close(g_saved);
    if (g_capture >= 0) ::close(g_capture);
    g_saved = g_capture = -1;
  }
}

LibpngLines::~LibpngLines() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (--g_depth > 0 || g_saved < 0) return;
  std::fflush(stderr);
  ::dup2(g_saved, 2);
  forward(g_capture, 2);
  ::close(g_saved);
  ::close(g_capture);
  g_saved = g_capture = -1;
}

}  // namespace ms::oiio
