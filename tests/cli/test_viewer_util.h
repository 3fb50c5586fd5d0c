// Helpers for the viewer's integration tests: the X server they share, a
// background process in its own process group (killed as one), polling a
// log file for a line, and image statistics.
#pragma once
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/image.h"

namespace ms::test {

inline bool on_path(const std::string& exe) {
  return std::system(("command -v " + exe + " >/dev/null 2>&1").c_str()) == 0;
}

// One Xvfb per test process, started on first use and stopped at exit. It
// picks a free display itself and writes its number to a pipe
// (-displayfd), so two runs at once never race for a number; the viewer runs
// under `env DISPLAY=:N`, so a test sees the product's own exit code, not
// a wrapper's. The screen fits the largest window a test opens.
class XServer {
 public:
  static const XServer& shared() {
    static const XServer server;
    return server;
  }
  const std::string& display() const { return display_; }  // ":N"; empty when Xvfb did not start
  ~XServer() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
  XServer(const XServer&) = delete;
  XServer& operator=(const XServer&) = delete;

 private:
  XServer() {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      prctl(PR_SET_PDEATHSIG, SIGTERM);  // a test killed by its timeout leaves no server behind
      setpgid(0, 0);                     // out of reach of a viewer's group kill
      close(fds[0]);
      if (!freopen("/dev/null", "r", stdin) || !freopen("/dev/null", "w", stdout) ||
          !freopen("/dev/null", "w", stderr))
        _exit(126);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    // The number and a newline arrive once the server accepts clients; EOF
    // first means it exited.
    std::string number;
    char c = 0;
    while (pid_ > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  pid_t pid_ = -1;
  std::string display_;
};

// `env`'s argument that puts a viewer on the shared X server.
inline std::string x_display() {
  const std::string& d = XServer::shared().display();
  if (d.empty()) ADD_FAILURE() << "Xvfb did not start (Debian: apt install xvfb)";
  return "DISPLAY=" + d;
}

class BackgroundProcess {
 public:
  BackgroundProcess(const std::vector<std::string>& argv, const std::filesystem::path& out,
                    const std::filesystem::path& err, const std::filesystem::path& cwd = {}) {
    pid_ = fork();
    if (pid_ == 0) {
      setpgid(0, 0);  // a group of its own: one kill reaches Xvfb too
      if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(126);
      if (!freopen(out.c_str(), "w", stdout) || !freopen(err.c_str(), "w", stderr) ||
          !freopen("/dev/null", "r", stdin))
        _exit(126);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      _exit(127);
    }
    if (pid_ > 0) setpgid(pid_, pid_);  // also here: no race with the child's own call
  }
  ~BackgroundProcess() {
    if (pid_ <= 0 || exited_) return;
    kill(-pid_, SIGTERM);
    if (wait_exit(5.0) < 0) {
      kill(-pid_, SIGKILL);
      wait_exit(5.0);
    }
  }
  BackgroundProcess(const BackgroundProcess&) = delete;
  BackgroundProcess& operator=(const BackgroundProcess&) = delete;

  bool started() const { return pid_ > 0; }
  bool running() {
    if (exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) finish(status);
    return !exited_;
  }
  void signal(int sig) { kill(pid_, sig); }
  // The exit code, or -1 when it is still running after `timeout_s`.
  int wait_exit(double timeout_s) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (running()) {
      if (std::chrono::steady_clock::now() > end) return -1;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return code_;
  }

 private:
  void finish(int status) {
    exited_ = true;
    code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  pid_t pid_ = -1;
  bool exited_ = false;
  int code_ = -1;
};

inline std::vector<std::string> file_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Polls `pred` every 20 ms; true when it held before `timeout_s`.
inline bool wait_until(const std::function<bool()>& pred, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return pred();
}

// The first line of `file` matching `re`, waiting up to `timeout_s`; empty when none came.
inline std::string wait_for_line(const std::filesystem::path& file, const std::string& re, double timeout_s) {
  const std::regex r(re);
  std::string found;
  wait_until(
      [&] {
        for (const std::string& line : file_lines(file))
          if (std::regex_search(line, r)) {
            found = line;
            return true;
          }
        return false;
      },
      timeout_s);
  return found;
}

// Integer value of `key=<n>` in a log line, -1 when absent.
inline double field(const std::string& line, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(line, m, std::regex("\\b" + key + "=([0-9.]+)"))) return -1;
  return std::stod(m[1]);
}

// Mean of (R - G) over the image: how red it is.
inline double redness(const Image& img) {
  double s = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) s += img.at(x, y, 0) - img.at(x, y, 1);
  return s / (static_cast<double>(img.width) * img.height);
}

inline double mean_abs_diff(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return 1e9;
  double s = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) s += std::abs(a.at(x, y, c) - b.at(x, y, c));
  return s / (3.0 * a.width * a.height);
}

// The largest difference of any channel of any pixel (1e9 for other sizes).
inline double max_abs_diff(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return 1e9;
  double m = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) m = std::max(m, static_cast<double>(std::abs(a.at(x, y, c) - b.at(x, y, c))));
  return m;
}

// A scene of the viewer tests' own (the shipped ones change with the
// tracer): a grey floor and a red ball of material `ball` at 160x90; each
// test writes its map (`seed.glsl`), a ball on the floor.
inline const char* const kBallScene = R"([scene]
map = "seed.glsl"
[camera]
position = [0.0, 1.6, -5.0]
target = [0.0, 0.8, 0.0]
[render]
width = 160
height = 90
tonemap = "aces"
[[lights]]
position = [4.0, 5.0, -1.5]
intensity = 2.0
[[materials]]
name = "floor"
color = [0.6, 0.6, 0.6]
[[materials]]
name = "ball"
color = [0.85, 0.10, 0.06]
)";

// kBallScene's map: the ball of `radius` on the floor. With heavy_lines >
// 0, plus a long function behind a branch no ray takes (p.y > 1e6), so the
// image stays the ball's while llvmpipe's compile and JIT take a second or
// more; its constant differs per process, so Mesa's disk shader cache
// never has it.
inline std::string ball_map(const std::string& radius, int heavy_lines = 0, const std::string& tail = "") {
  static const std::string salt =
      std::to_string((std::chrono::steady_clock::now().time_since_epoch().count() + getpid()) % 1000003);
  std::string s;
  if (heavy_lines > 0) {
    s += "float heavy(vec3 p) {\n  float a = " + salt + ".0;\n";
    for (int i = 0; i < heavy_lines; ++i)
      s += "  p = sin(p * " + std::to_string(1.0 + 0.01 * i) + " + p.yzx); a += p.x * p.z;\n";
    s += "  return a;\n}\n";
  }
  s += "vec2 map(vec3 p) {\n"
       "  vec2 ground = vec2(sdPlane(p, vec3(0.0, 1.0, 0.0), 0.0), MAT_FLOOR);\n"
       "  vec2 ball = vec2(sdSphere(p - vec3(0.0, 1.0, 0.0), " + radius + "), MAT_BALL);\n";
  if (heavy_lines > 0) s += "  if (p.y > 1e6) ball.x = heavy(p);\n";
  return s + "  return opUnion(ground, ball);\n}\n" + tail;
}

// The ball of radius 1 on the floor.
inline const std::string kBallMap = ball_map("1.0");
// A heavy map's length: its compile and JIT outlast many 160x90 frames on
// llvmpipe, and a test with it still takes seconds, not a minute.
inline constexpr int kHeavyLines = 30;

// Replace a file the way vim and VS Code save it: write a temporary next to
// it, then rename it over the original.
inline void save_by_rename(const std::filesystem::path& p, const std::string& text) {
  const std::filesystem::path tmp = p.parent_path() / ("." + p.filename().string() + ".swp~");
  { std::ofstream(tmp, std::ios::binary) << text; }
  std::filesystem::rename(tmp, p);
}

}  // namespace ms::test
