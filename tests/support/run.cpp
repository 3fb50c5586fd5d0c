#include "run.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace ms::test {
namespace fs = std::filesystem;

static std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

pid_t spawn_marchstudio(const std::vector<std::string>& args, const fs::path& dir, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    dup2(fd, 2);
    std::vector<std::string> all = {MARCH_BIN};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int count_files(const fs::path& dir, const std::string& prefix) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    n += name.rfind(prefix, 0) == 0 && name.find(".tmp") == std::string::npos;
  }
  return n;
}

void wait_for_files(const fs::path& dir, const std::string& prefix, int n, pid_t pid, const std::string& log) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (count_files(dir, prefix) < n) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0)
        << "the render ended before " << n << " files appeared" << (log.empty() ? "" : ": " + read_file(dir / log));
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << n << " files did not appear in 120 s";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

RunResult run_marchstudio(const std::vector<std::string>& args, const fs::path& cwd, const std::string& shell_prefix) {
  TempDir io;
  std::string cmd;
  if (!cwd.empty()) cmd += "cd " + quote(cwd.string()) + " && ";
  cmd += shell_prefix;
  cmd += quote(MARCH_BIN);
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " >" + quote((io / "out").string()) + " 2>" + quote((io / "err").string()) + " </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(io / "out");
  r.err = read_file(io / "err");
  return r;
}

}  // namespace ms::test
