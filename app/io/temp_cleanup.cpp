#include "io/temp_cleanup.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstring>
#include <map>
#include <string>

#include "io/atomic_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// The temporaries being written, where the handler can read them.
constexpr int kSlots = 4;
char g_temps[kSlots][PATH_MAX];
volatile std::sig_atomic_t g_count = 0;

extern "C" void remove_temps_and_exit(int sig) {
  for (int i = 0; i < g_count; ++i) ::unlink(g_temps[i]);
  ::_exit(128 + sig);
}

// The pid in a temporary's name: the digits after ".tmp" (before the
// extension, for a temporary that keeps it); 0 when there are none.
long temp_pid(const std::string& name) {
  const std::size_t at = name.rfind(".tmp");
  if (at == std::string::npos) return 0;
  std::size_t end = at + 4;
  while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
  if (end == at + 4 || end - at - 4 > 10) return 0;
  return std::stol(name.substr(at + 4, end - at - 4));
}

bool alive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

}  // namespace

RemoveTempOnSignal::RemoveTempOnSignal(const fs::path& target, Remove what) {
  const std::string temp = (what == Remove::file ? target : temp_path_for(target, ::getpid())).string();
  // Before the handler: it may run at once.
  if (g_count < kSlots && temp.size() < PATH_MAX) {
    slot_ = g_count;
    std::memcpy(g_temps[slot_], temp.c_str(), temp.size() + 1);
    g_count = slot_ + 1;
  }
  scope_.emplace(remove_temps_and_exit);
}

RemoveTempOnSignal::~RemoveTempOnSignal() {
  scope_.reset();  // the handler before it goes
  if (slot_ >= 0) g_count = slot_;
}

std::vector<fs::path> remove_dead_temps(const std::vector<fs::path>& targets) {
  std::map<fs::path, std::vector<fs::path>> by_dir;
  for (const fs::path& t : targets) by_dir[t.parent_path()].push_back(t);
  std::vector<fs::path> removed;
  for (const auto& [parent, in_dir] : by_dir) {
    std::error_code ec;
    std::vector<fs::path> found;
    for (const fs::directory_entry& e : fs::directory_iterator(parent.empty() ? fs::path(".") : parent, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind('.', 0) != 0 || name.find(".tmp") == std::string::npos) continue;
      if (std::any_of(in_dir.begin(), in_dir.end(), [&](const fs::path& t) { return is_temp_of(name, t); }))
        found.push_back(parent / name);
    }
    for (const fs::path& p : found) {
      const long pid = temp_pid(p.filename().string());
      if (pid == ::getpid() || alive(pid)) continue;  // ours (made later), or another run's still writing
      if (fs::remove(p, ec)) removed.push_back(p);
    }
  }
  return removed;
}

}  // namespace ms
