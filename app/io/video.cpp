#include "io/video.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "io/atomic_file.h"
#include "core/error.h"

extern char** environ;

namespace ms {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_video(Exit code, std::string what, std::string file, std::string hint = {}) {
  throw Error(ErrorInfo{code, std::move(file), 0, "--video", std::move(what), std::move(hint)});
}

}  // namespace

fs::path find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  const std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    // An empty PATH entry means the current directory, as for execvp.
    const fs::path dir = end == start ? fs::path(".") : fs::path(dirs.substr(start, end - start));
    const fs::path candidate = dir / program;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return {};
}

void check_video_path(const fs::path& out) {
  if (out.filename().empty() || out.extension().empty())
    fail_video(Exit::bad_input, "the video file needs a name with an extension", out.string(), "e.g. out.mp4");
  const fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail_video(Exit::bad_input, "output directory does not exist", dir.string());
  if (::access(dir.c_str(), W_OK) != 0) fail_video(Exit::bad_input, "output directory is not writable", dir.string());
}

void encode_video(const VideoJob& job) {
  const fs::path tmp = temp_path_for(job.output, ::getpid(), true);  // ffmpeg picks the container by the extension
  char fps[64];
  std::snprintf(fps, sizeof fps, "%.17g", job.fps);
  // yuv420p: what players accept; it needs even sizes, hence the pad.
  std::vector<std::string> args = {job.ffmpeg.string(), "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                   "-framerate", fps, "-start_number", std::to_string(job.first_frame),
                                   "-i", job.pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                   "-pix_fmt", "yuv420p", tmp.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int err = posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ))
    fail_video(Exit::system, std::string("cannot start ffmpeg: ") + std::strerror(err), job.ffmpeg.string());
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) fail_video(Exit::system, "lost track of ffmpeg", job.ffmpeg.string());
  std::error_code ec;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fs::remove(tmp, ec);
    const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status));
    fail_video(Exit::system, "ffmpeg failed (" + how + ") encoding the frames", job.output.string(),
               "its message is above; the frames are kept");
  }
  fs::rename(tmp, job.output, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail_video(Exit::system, "cannot rename the encoded video into place", job.output.string());
  }
}

}  // namespace ms
