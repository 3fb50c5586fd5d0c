#include "live/mesh_export.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "core/error.h"
#include "core/format.h"

extern char** environ;

namespace ms::live {
namespace fs = std::filesystem;

namespace {

// A --set value as TOML text: toml++ prints each node in its inline form
// (strings quoted, arrays and tables inline), which `mesh --set` parses back.
std::string toml_text(const toml::node& n) {
  std::ostringstream os;
  n.visit([&](const auto& v) { os << v; });
  return os.str();
}

std::string number_text(double v, bool integer) {
  return integer ? std::to_string(static_cast<long long>(v)) : printf_number("%.9g", v);
}

std::string uniform_text(const UniformValue& u, bool integer) {
  if (u.values.size() == 1) return u.name + "=" + number_text(u.values[0], integer);
  std::string s = u.name + "=[";
  for (std::size_t i = 0; i < u.values.size(); ++i) s += (i ? "," : "") + number_text(u.values[i], integer);
  return s + "]";
}

// The --uniform values the viewer started with, each replaced by the
// panel's value where the panel moved it; the panel's other moved values after.
std::vector<std::pair<UniformValue, bool>> uniform_values(const MeshExportSpec& spec) {
  std::vector<std::pair<UniformValue, bool>> out;
  for (const UniformValue& u : spec.assemble.uniforms) out.push_back({u, false});
  for (const SceneParam& p : spec.params) {
    if (p.value == p.initial) continue;
    UniformValue u{p.name, std::vector<double>(p.value.begin(), p.value.begin() + std::clamp(p.components, 1, 4))};
    auto same = std::find_if(out.begin(), out.end(), [&](const auto& o) { return o.first.name == p.name; });
    if (same != out.end()) *same = {u, p.is_int};
    else out.push_back({u, p.is_int});
  }
  return out;
}

const char* graph_eval_name(GraphEval e) {
  switch (e) {
    case GraphEval::inline_: return "inline";
    case GraphEval::interpreter: return "interpreter";
    case GraphEval::auto_: break;
  }
  return "auto";
}

std::string read_all(int fd) {
  std::string s;
  if (fd < 0 || ::lseek(fd, 0, SEEK_SET) < 0) return s;
  char buf[4096];
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) s.append(buf, static_cast<std::size_t>(n));
  return s;
}

// An unlinked temporary file: nothing is left behind, whatever happens.
int temp_fd() {
  const char* dir = std::getenv("TMPDIR");
  std::string path = std::string(dir && *dir ? dir : "/tmp") + "/marchstudio-mesh-XXXXXX";
  const int fd = ::mkstemp(path.data());
  if (fd >= 0) {
    ::unlink(path.c_str());
    ::fcntl(fd, F_SETFD, FD_CLOEXEC);  // the child gets it through dup2 only
  }
  return fd;
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

std::vector<std::string> mesh_export_args(const MeshExportSpec& spec) {
  const AssembleOptions& a = spec.assemble;
  std::vector<std::string> args = {"mesh", spec.input.string(), "--output=" + spec.output.string(), "--json",
                                   "--resolution=" + std::to_string(spec.resolution),
                                   "--time=" + printf_number("%.17g", spec.time)};
  // The `=` form throughout: a value that starts with '-' stays a value.
  if (!a.shader_dir.empty()) args.push_back("--shader-dir=" + a.shader_dir.string());
  for (const fs::path& d : a.allow_include) args.push_back("--allow-include=" + d.string());
  for (const auto& [name, value] : a.defines) args.push_back("--define=" + name + "=" + value);
  if (a.graph_eval != GraphEval::auto_) args.push_back(std::string("--graph-eval=") + graph_eval_name(a.graph_eval));
  if (!a.prune) args.push_back("--no-prune");
  if (!spec.preset.empty()) args.push_back("--preset=" + spec.preset);
  const std::string set_prefix = "--set ";
  for (const SceneOverride& o : spec.set) {
    const std::string key = o.flag.rfind(set_prefix, 0) == 0 ? o.flag.substr(set_prefix.size()) : o.flag;
    if (!o.value.empty()) args.push_back("--set=" + key + "=" + toml_text(o.value[0]));
  }
  for (const auto& [u, integer] : uniform_values(spec)) args.push_back("--uniform=" + uniform_text(u, integer));
  return args;
}

fs::path next_mesh_path(const fs::path& dir, const std::string& stem) {
  for (int n = 1;; ++n) {
    char num[16];
    std::snprintf(num, sizeof num, "%03d", n);
    const fs::path p = dir / (stem + "_mesh_" + num + ".obj");
    std::error_code ec;
    if (!fs::exists(p, ec) && !ec) return p;
    if (n >= 99999) return p;  // a directory full of them: let the child say why
  }
}

MeshExportResult mesh_export_result(int exit_code, const std::string& out, const std::string& err,
                                    const fs::path& output) {
  MeshExportResult r;
  r.exit_code = exit_code;
  if (exit_code == 0) {
    const nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
    r.ok = true;
    r.line = "wrote " + output.string();
    if (j.is_object() && j.contains("triangles"))
      r.line += " (" + std::to_string(j.value("triangles", 0ull)) + " triangles, " +
                (j.value("manifold", false) ? "watertight" : "NOT watertight") + ")";
    else if (j.is_object() && j.contains("band_voxels"))
      r.line += " (level set, " + std::to_string(j.value("band_voxels", 0ull)) + " voxels)";
    return r;
  }
  // The child's error is its last "marchstudio: " line that is not a warning.
  const std::string prefix = "marchstudio: ";
  std::istringstream in(err);
  for (std::string l; std::getline(in, l);)
    if (l.rfind(prefix, 0) == 0 && l.find(": warning: ") == std::string::npos) r.line = l.substr(prefix.size());
  if (r.line.empty())
    r.line = exit_code > 128 ? "the mesh export died (signal " + std::to_string(exit_code - 128) + ")"
                             : "the mesh export failed (exit " + std::to_string(exit_code) + ")";
  return r;
}

MeshExport::~MeshExport() {
  if (running()) wait();
  close_fd(out_fd_);
  close_fd(err_fd_);
}

void MeshExport::start(const MeshExportSpec& spec) {
  if (running()) fail_system("a mesh export is already running");
  close_fd(out_fd_);
  close_fd(err_fd_);
  out_fd_ = temp_fd();
  err_fd_ = temp_fd();
  if (out_fd_ < 0 || err_fd_ < 0) fail_system(std::string("no temporary file for the mesh export: ") + std::strerror(errno));
  std::vector<std::string> args = mesh_export_args(spec);
  args.insert(args.begin(), "marchstudio");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out_fd_, 1);
  posix_spawn_file_actions_adddup2(&fa, err_fd_, 2);
  // The window's X connection and GL files are the viewer's alone.
  posix_spawn_file_actions_addclosefrom_np(&fa, 3);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, "/proc/self/exe", &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) fail_system(std::string("cannot start the mesh export: ") + std::strerror(rc));
  pid_ = pid;
  output_ = spec.output;
}

std::optional<MeshExportResult> MeshExport::poll() {
  if (!running()) return std::nullopt;
  int status = 0;
  const pid_t got = ::waitpid(pid_, &status, WNOHANG);
  if (got == 0 || (got < 0 && errno == EINTR)) return std::nullopt;
  return finish(got == pid_ ? status : -1);
}

MeshExportResult MeshExport::wait() {
  int status = 0;
  pid_t got = -1;
  do got = ::waitpid(pid_, &status, 0);
  while (got < 0 && errno == EINTR);
  return finish(got == pid_ ? status : -1);
}

MeshExportResult MeshExport::finish(int status) {
  pid_ = -1;
  const int code = status < 0 ? 3 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  MeshExportResult r = mesh_export_result(code, read_all(out_fd_), read_all(err_fd_), output_);
  close_fd(out_fd_);
  close_fd(err_fd_);
  return r;
}

MeshExportResult export_mesh_now(const MeshExportSpec& spec) {
  try {
    MeshExport job;
    job.start(spec);
    return job.wait();
  } catch (const Error& e) {
    MeshExportResult r;
    r.exit_code = 3;
    r.line = e.what();
    return r;
  }
}

}  // namespace ms::live
