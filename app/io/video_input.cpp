#include "io/video_input.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "io/input_file.h"
#include "io/video.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Starts `args` with its stdout (and, when `capture_stderr`, its stderr) on
// a pipe whose read end comes back in `fd`; stdin and an uncaptured stderr
// are /dev/null. The child has its own process group, so a Ctrl-C meant for
// us (a sequence stops cleanly at a frame's end) does not end it under us,
// and it dies with us (PR_SET_PDEATHSIG) even by SIGKILL.
pid_t spawn(std::vector<std::string> args, bool capture_stderr, int& fd, const std::string& file) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int p[2];
  if (::pipe2(p, O_CLOEXEC) != 0) fail_system(std::string("cannot make a pipe for ffmpeg: ") + std::strerror(errno), file);
  const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(p[0]);
    ::close(p[1]);
    if (null >= 0) ::close(null);
    fail_system(std::string("cannot start ffmpeg: ") + std::strerror(errno), file);
  }
  if (pid == 0) {  // only async-signal-safe calls here
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    ::dup2(p[1], 1);
    ::dup2(capture_stderr ? p[1] : null, 2);
    if (null >= 0) ::dup2(null, 0);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(p[1]);
  if (null >= 0) ::close(null);
  fd = p[0];
  return pid;
}

[[noreturn]] void fail_video(const fs::path& file, const std::string& why) {
  fail_input("cannot decode the video file: " + why, file.string(), 0, {},
             "marchstudio reads video inputs through ffmpeg; this file is not one it can decode");
}

// The whole output of a short child (a probe), and its exit status. It has
// kVideoProbeSeconds, whatever --timeout says: a file that makes it wait (a
// concat script naming a FIFO) is ended and refused, not waited for.
std::string run_capture(const std::vector<std::string>& args, int& status, const fs::path& file) {
  int fd = -1;
  const pid_t pid = spawn(args, true, fd, file.string());
  const Deadline bound = Deadline::after(kVideoProbeSeconds);
  std::string out;
  char buf[4096];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const int r = ::poll(&p, 1, 100);
    if (bound.expired()) {
      ::close(fd);
      end_child(pid);
      fail_video(file, fs::path(args[0]).filename().string() + " did not finish probing it within " +
                           std::to_string(static_cast<int>(kVideoProbeSeconds)) + " s");
    }
    if (r < 0 && errno != EINTR) break;
    if (r <= 0) continue;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) out.append(buf, static_cast<size_t>(n));
    else if (n == 0 || errno != EINTR) break;
  }
  ::close(fd);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return out;
}

// ffmpeg's reason, one line: its last line, without the file's URL.
std::string last_line(const std::string& out, const fs::path& file) {
  std::istringstream in(out);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  const std::string prefix = ffmpeg_file_url(file) + ": ";
  if (last.compare(0, prefix.size(), prefix) == 0) last = last.substr(prefix.size());
  return last.empty() ? "ffmpeg found no video in it" : last;
}

double rate(const std::string& s) {  // "30000/1001", "25", "0/0"
  const size_t slash = s.find('/');
  const double num = std::atof(s.substr(0, slash).c_str());
  const double den = slash == std::string::npos ? 1.0 : std::atof(s.substr(slash + 1).c_str());
  return den > 0 && num > 0 ? num / den : 0.0;
}

// ffprobe's flat report of the first video stream.
VideoInfo probe_with_ffprobe(const fs::path& ffprobe, const fs::path& file) {
  int status = 0;
  const std::string out = run_capture(
      {ffprobe.string(), "-v", "error", "-protocol_whitelist", "file", "-select_streams", "v:0", "-show_entries",
       "stream=width,height,avg_frame_rate,r_frame_rate,duration:format=duration", "-of", "flat", "-i",
       ffmpeg_file_url(file)},
      status, file);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail_video(file, last_line(out, file));
  VideoInfo v;
  double stream_duration = 0.0, format_duration = 0.0, avg = 0.0, r = 0.0;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    const size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq);
    std::string val = line.substr(eq + 1);
    if (val.size() >= 2 && val.front() == '"') val = val.substr(1, val.size() - 2);
    if (key == "streams.stream.0.width") v.width = std::atoi(val.c_str());
    else if (key == "streams.stream.0.height") v.height = std::atoi(val.c_str());
    else if (key == "streams.stream.0.avg_frame_rate") avg = rate(val);
    else if (key == "streams.stream.0.r_frame_rate") r = rate(val);
    else if (key == "streams.stream.0.duration") stream_duration = std::atof(val.c_str());
    else if (key == "format.duration") format_duration = std::atof(val.c_str());
  }
  if (v.width <= 0 || v.height <= 0) fail_video(file, "it holds no video stream");
  v.fps = avg > 0 ? avg : r;
  v.duration = stream_duration > 0 ? stream_duration : format_duration;
  return v;
}

// Without ffprobe: what `ffmpeg -i FILE` says of it on stderr.
VideoInfo probe_with_ffmpeg(const fs::path& ffmpeg, const fs::path& file) {
  int status = 0;
  const std::string out =
      run_capture({ffmpeg.string(), "-hide_banner", "-nostdin", "-protocol_whitelist", "file", "-i",
                   ffmpeg_file_url(file)},
                  status, file);
  VideoInfo v;
  std::smatch m;
  static const std::regex duration(R"(Duration: (\d+):(\d+):(\d+(?:\.\d+)?))");
  if (std::regex_search(out, m, duration))
    v.duration = std::stod(m[1]) * 3600 + std::stod(m[2]) * 60 + std::stod(m[3]);
  std::istringstream in(out);
  std::string line;
  static const std::regex size(R"(, (\d+)x(\d+)[ ,])"), fps(R"(, (\d+(?:\.\d+)?)(k?) fps)"),
      tbr(R"(, (\d+(?:\.\d+)?)(k?) tbr)");
  while (std::getline(in, line)) {
    if (line.find("Stream #") == std::string::npos || line.find(": Video: ") == std::string::npos) continue;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), size); it != std::sregex_iterator(); ++it)
      if (std::stoi((*it)[1]) > 0 && std::stoi((*it)[2]) > 0) {
        v.width = std::stoi((*it)[1]);
        v.height = std::stoi((*it)[2]);
        break;
      }
    if (std::regex_search(line, m, fps) || std::regex_search(line, m, tbr))
      v.fps = std::stod(m[1]) * (m[2] == "k" ? 1000.0 : 1.0);
    break;
  }
  if (v.width <= 0 || v.height <= 0) fail_video(file, last_line(out, file));
  return v;
}

}  // namespace

long video_frame_index(const VideoInfo& v, double t) {
  if (!(t > 0) || v.duration <= 0 || v.fps <= 0) return 0;
  const double in_loop = std::fmod(t, v.duration);
  const long n = static_cast<long>(std::floor(in_loop * v.fps + 1e-4));
  return std::min(std::max(n, 0L), v.frames - 1);
}

VideoStream::VideoStream(fs::path ffmpeg, fs::path file, VideoInfo info)
    : ffmpeg_(std::move(ffmpeg)), file_(std::move(file)), info_(info) {}

VideoStream::~VideoStream() { stop(); }

void VideoStream::stop() {
  if (fd_ >= 0) ::close(fd_);
  if (pid_ > 0) end_child(pid_);
  fd_ = -1;
  pid_ = -1;
}

void VideoStream::start(long n) {
  stop();
  std::vector<std::string> args = {ffmpeg_.string(), "-hide_banner", "-loglevel", "error", "-nostdin",
                                   "-noautorotate", "-protocol_whitelist", "file"};
  if (n > 0) {  // accurate seek: decoding starts at the keyframe before, frames before this time are dropped
    char at[64];
    std::snprintf(at, sizeof at, "%.9f", (static_cast<double>(n) - 0.5) / info_.fps);
    args.insert(args.end(), {"-ss", at});
  }
  args.insert(args.end(), {"-i", ffmpeg_file_url(file_), "-map", "0:v:0", "-an", "-sn", "-dn", "-vsync",
                           "passthrough", "-f", "rawvideo", "-pix_fmt", "rgba", "-"});
  pid_ = spawn(std::move(args), false, fd_, file_.string());
  next_ = n;
}

bool VideoStream::read_next(const Deadline* deadline) {
  const size_t size = static_cast<size_t>(info_.width) * info_.height * 4;
  next_pixels_.resize(size);
  size_t got = 0;
  Deadline stall = Deadline::after(kVideoStallSeconds);  // renewed by every byte that comes
  while (got < size) {
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, 100);
    if (r < 0 && errno != EINTR) return false;
    if (deadline && deadline->expired()) {
      stop();
      deadline->check("decoding the video " + file_.string());
    }
    if (stall.expired()) {
      stop();
      fail_video(file_, "ffmpeg gave no frame data for " + std::to_string(static_cast<int>(kVideoStallSeconds)) + " s");
    }
    if (r <= 0) continue;
    const ssize_t k = ::read(fd_, next_pixels_.data() + got, size - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    got += static_cast<size_t>(k);
    stall = Deadline::after(kVideoStallSeconds);
  }
  return true;
}

const std::vector<std::uint8_t>& VideoStream::frame(long n, const Deadline* deadline) {
  n = std::min(std::max(n, 0L), info_.frames - 1);
  if (end_ >= 0 && n >= end_) n = end_ - 1;  // past what decodes: the last frame that did
  if (n == have_) return pixels_;
  // Forward within a few seconds: decode on; else (back, a loop, far ahead) seek.
  const long ahead = std::max(48L, static_cast<long>(2 * info_.fps));
  if (pid_ < 0 || n < next_ || n - next_ > ahead) start(n);
  for (;;) {
    while (next_ <= n) {
      if (!read_next(deadline)) break;
      std::swap(pixels_, next_pixels_);
      have_ = next_++;
    }
    if (have_ == n) return pixels_;
    // The stream ended before frame n: the frames end at next_.
    stop();
    end_ = next_;
    if (have_ >= 0 && have_ == next_ - 1) return pixels_;
    if (next_ == 0) fail_input("ffmpeg decoded no frame from the video file", file_.string());
    n = next_ - 1;  // a seek started past the end: the frame before it
    start(n);
  }
}

std::shared_ptr<VideoStream> open_video(const fs::path& file, const std::string& where) {
  const fs::path ffmpeg = find_on_path("ffmpeg");
  if (ffmpeg.empty())
    fail_input(where + ": video inputs need ffmpeg, which is not on PATH", file.string(), 0, {},
               "install ffmpeg; tools/install-deps.sh lists it");
  const std::string problem = input_file_problem(file);
  if (!problem.empty()) fail_input("cannot read the video file: " + problem, file.string());
  const fs::path ffprobe = find_on_path("ffprobe");
  VideoInfo v = ffprobe.empty() ? probe_with_ffmpeg(ffmpeg, file) : probe_with_ffprobe(ffprobe, file);
  if (v.fps <= 0 || !std::isfinite(v.fps)) fail_video(file, "ffmpeg reports no frame rate for it");
  if (v.duration <= 0 || !std::isfinite(v.duration)) fail_video(file, "ffmpeg reports no duration for it");
  if (static_cast<double>(v.width) * v.height > 16384.0 * 16384.0) fail_video(file, "its frames are too large");
  v.frames = std::max(1L, std::lround(v.duration * v.fps));
  return std::make_shared<VideoStream>(ffmpeg, file, v);
}

}  // namespace ms
