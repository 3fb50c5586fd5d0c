#include "io/video.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <algorithm>
#include <cctype>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "io/atomic_file.h"
#include "core/format.h"
#include "core/error.h"


namespace ms {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_video(Exit code, std::string what, std::string file, std::string hint = {}) {
  throw Error(ErrorInfo{code, std::move(file), 0, "--video", std::move(what), std::move(hint), {}});
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

std::string ffmpeg_file_url(const fs::path& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec);
  return "file:" + (ec ? p : abs).string();
}

double encode_seconds(int frames) { return 60.0 + 10.0 * std::max(frames, 0); }

void check_video_path(const fs::path& out) {
  if (out.filename().empty() || out.extension().empty())
    fail_video(Exit::bad_input, "the video file needs a name with an extension", out.string(), "e.g. out.mp4");
  // A directory or a socket is refused; a FIFO or a device is written to (encode_video).
  if (output_kind(out, "--video") == OutputKind::replace)
    check_output_directory(out.parent_path().empty() ? fs::path(".") : out.parent_path(), "--video");
}

void end_child(pid_t pid) {
  ::kill(pid, SIGTERM);
  int status = 0;
  for (int i = 0; i < 200; ++i) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return;
    ::usleep(10000);
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

bool encode_video(const VideoJob& job) {
  // A FIFO or a device is written in place, never renamed over (io/atomic_file.h).
  const bool through = output_kind(job.output, "--video") == OutputKind::through;
  // ffmpeg picks the container by the extension, which the temporary keeps.
  const fs::path tmp = through ? job.output : temp_path_for(job.output, ::getpid(), true);
  std::error_code mk;
  if (!job.output.parent_path().empty()) fs::create_directories(job.output.parent_path(), mk);
  const std::string fps = printf_number("%.17g", job.fps);  // exact: ffmpeg reads the rate back
  // yuv420p: what players accept; it needs even sizes, hence the pad.
  std::vector<std::string> args = {job.ffmpeg.string(), "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                   "-protocol_whitelist", "file", "-framerate", fps, "-start_number",
                                   std::to_string(job.first_frame), "-i", ffmpeg_file_url(job.pattern),
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p",
                                   "-protocol_whitelist", "file", ffmpeg_file_url(tmp)};
  const Deadline own = Deadline::after(encode_seconds(job.frames));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) fail_video(Exit::system, std::string("cannot start ffmpeg: ") + std::strerror(errno), job.ffmpeg.string());
  if (pid == 0) {
    // Only async-signal-safe calls here. If marchstudio dies, even by
    // SIGKILL, ffmpeg goes too instead of writing on as an orphan.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  std::error_code ec;
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) fail_video(Exit::system, "lost track of ffmpeg", job.ffmpeg.string());
    const bool stop = job.stop_signal && job.stop_signal() != 0;
    if (stop || job.deadline.expired() || own.expired()) {
      end_child(pid);
      if (!through) fs::remove(tmp, ec);
      if (stop) return false;
      job.deadline.check("encoding the video");
      char bound[32];
      std::snprintf(bound, sizeof bound, "%.0f", own.seconds());
      fail_video(Exit::system, std::string("ffmpeg did not finish encoding within ") + bound + " s", job.output.string(),
                 "60 s and 10 s a frame; the frames are kept");
    }
    ::usleep(10000);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    if (!through) fs::remove(tmp, ec);
    const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status));
    fail_video(Exit::system, "ffmpeg failed (" + how + ") encoding the frames", job.output.string(),
               "its message is above; the frames are kept");
  }
  if (!through) fs::rename(tmp, job.output, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail_video(Exit::system, "cannot rename the encoded video into place", job.output.string());
  }
  return true;
}

std::vector<fs::path> remove_stale_video_temps(const fs::path& output) {
  std::vector<fs::path> removed;
  const fs::path dir = output.parent_path().empty() ? fs::path(".") : output.parent_path();
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!is_temp_of(name, output)) continue;
    // The pid is the digits before the extension; a live one is another encode.
    const std::string ext = output.extension().string();
    const bool ext_last = name.size() >= ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
    const size_t end = ext_last ? name.size() - ext.size() : name.size();
    size_t start = end;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
    const long pid = std::atol(name.substr(start, end - start).c_str());
    if (pid > 0 && pid != ::getpid() && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM)) continue;
    if (fs::remove(e.path(), ec)) removed.push_back(e.path());
  }
  return removed;
}

}  // namespace ms
