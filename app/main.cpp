// marchstudio: one program, subcommands dispatched by cli/, on a thread
// whose stack a deep shader compile cannot overflow (core/big_stack.h).
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

#include "cli/cli.h"
#include "core/big_stack.h"

namespace {

// Started with stdin, stdout or stderr closed (`2>&-`), the first file we
// open would take that number: a frame would get the progress lines, or a
// pipe to ffprobe would land on fd 1. /dev/null holds each closed one.
void open_standard_fds() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int null = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (null < 0) ::_exit(3);  // nothing safe to write to, nor a way to say so
    // open() takes the lowest free number, this one: those below are open by now.
    if (null != fd) {
      ::dup2(null, fd);
      ::close(null);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  open_standard_fds();
  // A file size limit (ulimit -f) then fails the write, which io/atomic_file.h
  // reports as it reports a full disk, instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  return ms::finish_output(ms::run_on_big_stack([&] { return ms::run_cli(argc, argv); }));
}
