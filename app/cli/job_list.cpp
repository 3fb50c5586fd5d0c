#include "cli/job_list.h"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string_view>

#include "cli/dispatch_flag.h"
#include "cli/input_flags.h"
#include "cli/mesh_cmd.h"
#include "cli/override_flags.h"
#include "cli/render_cmd.h"
#include "pipeline/input.h"
#include "core/suggest.h"
#include "importers/json_brief.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::size_t kMaxLineBytes = 1 << 20;  // a job is a few hundred bytes; a megabyte is no job

// What a key's handler knows: the value, where relative paths start, the
// key for errors.
struct KeyValue {
  const json& value;
  const fs::path& base;
  const std::string& key;
};

[[noreturn]] void wrong_type(const KeyValue& kv, const std::string& expected) {
  fail_input("'" + kv.key + "' must be " + expected + ", not " + json_brief(kv.value), {}, 0, kv.key);
}
std::string text(const KeyValue& kv) {
  if (!kv.value.is_string()) wrong_type(kv, "a string");
  return kv.value.get<std::string>();
}
std::string path(const KeyValue& kv) {
  const fs::path p = text(kv);
  return (p.is_absolute() || kv.base.empty() ? p : kv.base / p).string();
}
double number(const KeyValue& kv) {
  if (!kv.value.is_number()) wrong_type(kv, "a number");
  const double d = kv.value.get<double>();
  if (!std::isfinite(d)) wrong_type(kv, "a finite number");
  return d;
}
int integer(const KeyValue& kv) {
  if (!kv.value.is_number_integer() || std::abs(kv.value.get<double>()) > 1e9) wrong_type(kv, "an integer");
  return kv.value.get<int>();
}
bool boolean(const KeyValue& kv) {
  if (!kv.value.is_boolean()) wrong_type(kv, "true or false");
  return kv.value.get<bool>();
}
// A list key: one string or an array of strings, each through `each`.
void strings(const KeyValue& kv, const std::function<std::string(const KeyValue&)>& read,
             const std::function<void(const std::string&)>& each) {
  if (!kv.value.is_array()) return each(read(kv));
  for (const json& v : kv.value) each(read(KeyValue{v, kv.base, kv.key}));
}
// --disable and --aov take "a,b" as well as repeats.
void comma_list(const KeyValue& kv, std::vector<std::string>& out) {
  strings(kv, text, [&](const std::string& s) {
    for (std::size_t at = 0;;) {
      const std::size_t comma = s.find(',', at);
      out.push_back(s.substr(at, comma - at));
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
  });
}

using Handler = std::function<void(const KeyValue&, RenderArgs&)>;

const std::map<std::string, Handler>& handlers() {
  static const std::map<std::string, Handler> h = {
      {"scene", [](const KeyValue& kv, RenderArgs& a) { a.input = path(kv); }},
      {"output", [](const KeyValue& kv, RenderArgs& a) { a.output = job_output(text(kv), kv.base, a.output_dir).string(); }},
      {"size", [](const KeyValue& kv, RenderArgs& a) { a.size = parse_size_flag(text(kv)); }},
      {"spp", [](const KeyValue& kv, RenderArgs& a) { a.spp = integer(kv); }},
      {"time",
       [](const KeyValue& kv, RenderArgs& a) {
         a.time = number(kv);
       }},
      {"frame",
       [](const KeyValue& kv, RenderArgs& a) {
         a.frame = integer(kv);
       }},
      {"fps",
       [](const KeyValue& kv, RenderArgs& a) {
         a.fps = number(kv);
       }},
      {"backend", [](const KeyValue& kv, RenderArgs& a) { a.backend = parse_backend(text(kv)); }},
      {"shader-dir", [](const KeyValue& kv, RenderArgs& a) { a.load.shader_dir = path(kv); }},
      {"preset", [](const KeyValue& kv, RenderArgs& a) { a.load.preset = text(kv); }},
      {"disable", [](const KeyValue& kv, RenderArgs& a) { comma_list(kv, a.load.disable); }},
      {"aov", [](const KeyValue& kv, RenderArgs& a) { comma_list(kv, a.aov); }},
      {"define",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) { a.load.defines.push_back(parse_defines({s}).front()); });
       }},
      {"allow-include",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, path, [&](const std::string& s) { a.load.allow_include.push_back(s); });
       }},
      {"set",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) {
           a.load.overrides.set.push_back(parse_set_flag(s));
           a.load.overrides.as_given.push_back("--set " + s);
         });
       }},
      {"uniform",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) {
           a.load.overrides.uniforms.push_back(parse_uniform_flag(s));
           a.load.overrides.as_given.push_back("--uniform " + s);
         });
       }},
      {"strict", [](const KeyValue& kv, RenderArgs& a) { a.strict = boolean(kv); }},
      {"no-specialize", [](const KeyValue& kv, RenderArgs& a) { a.load.no_specialize = boolean(kv); }},
      {"dispatch", [](const KeyValue& kv, RenderArgs& a) { a.dispatch = parse_dispatch(text(kv)); }},
      {"timeout", [](const KeyValue& kv, RenderArgs& a) { a.timeout = number(kv); }},
      {"media-dir", [](const KeyValue& kv, RenderArgs& a) { a.load.shadertoy.media_dir = path(kv); }},
      {"missing-media",
       [](const KeyValue& kv, RenderArgs& a) { a.load.shadertoy.missing_media = parse_missing_media(text(kv)); }},
      {"mouse", [](const KeyValue& kv, RenderArgs& a) { a.load.shadertoy.mouse = parse_mouse_flag(text(kv)); }},
      {"graph-eval", [](const KeyValue& kv, RenderArgs& a) { a.load.graph_eval = parse_graph_eval(text(kv)); }},
      {"no-prune", [](const KeyValue& kv, RenderArgs& a) { a.load.no_prune = boolean(kv); }},
  };
  return h;
}

// The keys of a render line that mean nothing to a mesh: an image's size,
// samples, channels, dispatch and Shadertoy's inputs.
bool render_only(const std::string& key) {
  static const char* const keys[] = {"size", "spp", "frame", "fps", "aov", "dispatch", "strict",
                                     "media-dir", "missing-media", "mouse"};
  for (const char* k : keys)
    if (key == k) return true;
  return false;
}

// A mesh line's own keys: `mesh`'s flags without the dashes.
using MeshHandler = std::function<void(const KeyValue&, MeshArgs&)>;

int in_range(const KeyValue& kv, int lo, int hi) {
  if (!kv.value.is_number_integer() || kv.value.get<double>() < lo || kv.value.get<double>() > hi)
    wrong_type(kv, "an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
  return kv.value.get<int>();
}

const std::map<std::string, MeshHandler>& mesh_handlers() {
  static const std::map<std::string, MeshHandler> h = {
      {"resolution", [](const KeyValue& kv, MeshArgs& m) { m.resolution = in_range(kv, 8, kMaxMeshCells); }},
      {"voxel",
       [](const KeyValue& kv, MeshArgs& m) {
         m.voxel = number(kv);
         if (m.voxel <= 0) wrong_type(kv, "a positive number");
       }},
      {"bounds",
       [](const KeyValue& kv, MeshArgs& m) {
         if (!kv.value.is_array() || kv.value.size() != 6) wrong_type(kv, "[x0, y0, z0, x1, y1, z1]");
         m.bounds.clear();
         for (const json& v : kv.value) m.bounds.push_back(static_cast<float>(number(KeyValue{v, kv.base, kv.key})));
       }},
      {"planes", [](const KeyValue& kv, MeshArgs& m) { m.planes = boolean(kv); }},
      {"band", [](const KeyValue& kv, MeshArgs& m) { m.band = in_range(kv, 1, 64); }},
  };
  return h;
}

// A line is a mesh when it has a "mesh" object or its output is a mesh file.
bool is_mesh_line(const json& obj) {
  if (obj.contains("mesh")) return true;
  const auto out = obj.find("output");
  return out != obj.end() && out->is_string() && mesh_format_for(fs::path(out->get<std::string>())).has_value();
}

[[noreturn]] void unknown_key(const std::string& key, const std::string& pointer, const std::vector<std::string>& known) {
  std::vector<std::string_view> names;
  for (const std::string& k : known) names.push_back(k);
  fail_input("unknown key '" + pointer + "'", {}, 0, pointer, did_you_mean(key, names));
}

// A mesh line's "mesh" object: the mesh keys, each named by its JSON pointer.
void apply_mesh_object(const KeyValue& kv, MeshArgs& m) {
  if (!kv.value.is_object()) wrong_type(kv, "an object of mesh keys, e.g. {\"resolution\": 64}");
  std::vector<std::string> known;
  for (const auto& [name, h] : mesh_handlers()) known.push_back(name);
  for (const auto& [key, value] : kv.value.items()) {
    const std::string pointer = "/mesh/" + key;
    const auto h = mesh_handlers().find(key);
    if (h == mesh_handlers().end()) unknown_key(key, pointer, known);
    h->second(KeyValue{value, kv.base, pointer}, m);
  }
}

// The render flags a mesh shares, from the line over the command line's.
MeshArgs mesh_args_from(const RenderArgs& a) {
  MeshArgs m;
  m.input = a.input;
  m.output = a.output;
  m.time = a.time;
  m.verbose = a.verbose;
  m.timeout = a.timeout;
  m.backend = a.backend;
  m.load = a.load;
  m.load.shadertoy = {};  // a mesh line takes no Shadertoy keys (render_only())
  return m;
}

// One line's object over the defaults, then the same checks as the flags:
// into e.job, or for a mesh line into e.mesh.
void job_from_line(const std::string& line, const RenderArgs& defaults, const fs::path& base,
                   const DefaultOutput& default_output, BatchEntry& e) {
  json obj;
  try {
    obj = json::parse(line);
  } catch (const json::exception& ex) {
    std::string what = ex.what();  // "[json.exception.parse_error.101] parse error at ..."
    if (const std::size_t close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
    fail_input("not a JSON object: " + what, {}, 0, {}, "one object per line, e.g. {\"scene\": \"a.toml\"}");
  }
  if (!obj.is_object()) fail_input("not a JSON object: " + json_brief(obj), {}, 0, {}, "one object per line");
  const bool mesh = is_mesh_line(obj);
  RenderArgs a = defaults;
  a.output.clear();  // -o names one file; a job names its own
  a.input.clear();
  MeshArgs m;
  std::vector<std::pair<std::string, const json*>> mesh_keys;  // applied once the shared keys are
  for (const auto& [key, value] : obj.items()) {
    if (key == "mesh" || mesh_handlers().count(key)) {
      if (!mesh)
        fail_input("'" + key + "' is a mesh key, and this line's output is an image", {}, 0, key,
                   "name the output .obj, .ply, .stl, .glb or .vdb to mesh the scene");
      mesh_keys.emplace_back(key, &value);
      continue;
    }
    const auto h = handlers().find(key);
    if (h == handlers().end()) unknown_key(key, key, job_keys());
    if (mesh && render_only(key))
      fail_input("'" + key + "' makes no sense for a mesh (its output is a mesh file)", {}, 0, key);
    h->second(KeyValue{value, base, key}, a);
  }
  if (a.input.empty()) fail_input("the job has no 'scene'", {}, 0, "scene", "e.g. {\"scene\": \"scenes/seed.toml\"}");
  if (!mesh) {
    e.job = make_render_job(a, a.input, a.output.empty() ? default_output(a.input) : fs::path(a.output));
    return;
  }
  m = mesh_args_from(a);
  for (const auto& [key, value] : mesh_keys) {
    const KeyValue kv{*value, base, key};
    if (key == "mesh") apply_mesh_object(kv, m);
    else mesh_handlers().at(key)(kv, m);
  }
  // No "output": the batch's name for the input, a mesh's extension.
  if (m.output.empty()) m.output = default_output(a.input).replace_extension(".obj").string();
  e.mesh = make_mesh_job(m);
}

}  // namespace

fs::path job_output(const fs::path& output, const fs::path& job_dir, const std::string& output_dir) {
  if (output.is_absolute()) return output;
  if (!output_dir.empty()) return fs::path(output_dir) / output;
  return job_dir.empty() ? output : job_dir / output;
}

const std::vector<std::string>& job_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& [name, h] : handlers()) k.push_back(name);
    for (const auto& [name, h] : mesh_handlers()) k.push_back(name);
    k.push_back("mesh");
    std::sort(k.begin(), k.end());
    return k;
  }();
  return keys;
}

JobFile::JobFile(const fs::path& file, const RenderArgs& defaults, DefaultOutput default_output)
    : file_(file), defaults_(defaults), default_output_(std::move(default_output)), buf_(std::size_t{1} << 16) {
  // A FIFO named here is refused rather than waited on.
  std::string why;
  fd_ = open_regular_file(file, why);
  if (fd_ >= 0) return;
  std::error_code ec;
  if (fs::is_regular_file(file, ec)) fail_system("cannot read the job file", file.string());  // unreadable
  fail_input("no such job file (or not a regular file)", file.string(), 0, "--jobs");
}

JobFile::~JobFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool JobFile::read_line(bool& too_long) {
  line_.clear();
  too_long = false;
  bool any = false;
  for (;;) {
    if (pos_ == end_) {
      const ssize_t n = ::read(fd_, buf_.data(), buf_.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) fail_system("cannot read the job file", file_.string());
      if (n == 0) return any;
      pos_ = 0;
      end_ = static_cast<std::size_t>(n);
    }
    any = true;
    const char* from = buf_.data() + pos_;
    const char* nl = static_cast<const char*>(std::memchr(from, '\n', end_ - pos_));
    const std::size_t take = nl ? static_cast<std::size_t>(nl - from) : end_ - pos_;
    // Past the limit the rest of the line is read past, never kept.
    if (!too_long && line_.size() + take > kMaxLineBytes + 1) {
      too_long = true;
      std::string().swap(line_);
    }
    if (!too_long) line_.append(from, take);
    pos_ += take;
    if (nl) {
      ++pos_;
      return true;
    }
  }
}

std::optional<BatchEntry> JobFile::next() {
  for (;;) {
    bool too_long = false;
    if (!read_line(too_long)) return std::nullopt;
    ++number_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    if (!too_long && line_.find_first_not_of(" \t") == std::string::npos) continue;
    BatchEntry e;
    e.label = file_.string() + ":" + std::to_string(number_);
    try {
      if (too_long || line_.size() > kMaxLineBytes) fail_input("the line is over 1 MiB: no job is that long");
      job_from_line(line_, defaults_, file_.parent_path(), default_output_, e);
      if (e.job) e.job->label = e.label;
      if (e.mesh) e.mesh->frame.label = e.label;
    } catch (const Error& err) {
      ErrorInfo info = err.info();  // blamed on FILE:LINE unless it names a file of its own
      if (info.file.empty()) {
        info.file = file_.string();
        info.line = number_;
      }
      e.error.emplace(info);
    }
    return e;
  }
}

int JobFile::count_jobs(const fs::path& file) {
  std::string why;
  const int fd = open_regular_file(file, why);
  if (fd < 0) return 0;
  std::vector<char> buf(std::size_t{1} << 16);
  int count = 0;
  bool blank = true;
  for (;;) {
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    for (ssize_t i = 0; i < n; ++i) {
      const char c = buf[static_cast<std::size_t>(i)];
      if (c == '\n') {
        count += blank ? 0 : 1;
        blank = true;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        blank = false;
      }
    }
  }
  ::close(fd);
  return count + (blank ? 0 : 1);
}

}  // namespace ms
