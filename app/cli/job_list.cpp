#include "cli/job_list.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <string_view>

#include "cli/dispatch_flag.h"
#include "cli/input_flags.h"
#include "cli/override_flags.h"
#include "cli/render_cmd.h"
#include "pipeline/input.h"
#include "scene/suggest.h"
#include "importers/json_brief.h"

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
         a.time_set = true;
       }},
      {"frame",
       [](const KeyValue& kv, RenderArgs& a) {
         a.frame = integer(kv);
         a.frame_set = true;
       }},
      {"fps",
       [](const KeyValue& kv, RenderArgs& a) {
         a.fps = number(kv);
         a.fps_set = true;
       }},
      {"backend", [](const KeyValue& kv, RenderArgs& a) { a.backend = parse_backend(text(kv)); }},
      {"shader-dir", [](const KeyValue& kv, RenderArgs& a) { a.shader_dir = path(kv); }},
      {"preset", [](const KeyValue& kv, RenderArgs& a) { a.preset = text(kv); }},
      {"disable", [](const KeyValue& kv, RenderArgs& a) { comma_list(kv, a.disable); }},
      {"aov", [](const KeyValue& kv, RenderArgs& a) { comma_list(kv, a.aov); }},
      {"define",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) { a.defines.push_back(parse_defines({s}).front()); });
       }},
      {"allow-include",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, path, [&](const std::string& s) { a.allow_include.push_back(s); });
       }},
      {"set",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) {
           a.overrides.set.push_back(parse_set_flag(s));
           a.overrides.as_given.push_back("--set " + s);
         });
       }},
      {"uniform",
       [](const KeyValue& kv, RenderArgs& a) {
         strings(kv, text, [&](const std::string& s) {
           a.overrides.uniforms.push_back(parse_uniform_flag(s));
           a.overrides.as_given.push_back("--uniform " + s);
         });
       }},
      {"strict", [](const KeyValue& kv, RenderArgs& a) { a.strict = boolean(kv); }},
      {"no-specialize", [](const KeyValue& kv, RenderArgs& a) { a.no_specialize = boolean(kv); }},
      {"dispatch", [](const KeyValue& kv, RenderArgs& a) { a.dispatch = parse_dispatch(text(kv)); }},
      {"timeout", [](const KeyValue& kv, RenderArgs& a) { a.timeout = number(kv); }},
      {"media-dir", [](const KeyValue& kv, RenderArgs& a) { a.shadertoy.media_dir = path(kv); }},
      {"missing-media",
       [](const KeyValue& kv, RenderArgs& a) { a.shadertoy.missing_media = parse_missing_media(text(kv)); }},
      {"mouse", [](const KeyValue& kv, RenderArgs& a) { a.shadertoy.mouse = parse_mouse_flag(text(kv)); }},
  };
  return h;
}

// One line's object over the defaults, then the same checks as the flags.
FrameJob job_from_line(const std::string& line, const RenderArgs& defaults, const fs::path& base,
                        const DefaultOutput& default_output) {
  json obj;
  try {
    obj = json::parse(line);
  } catch (const json::exception& e) {
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    if (const std::size_t close = what.find("] "); close != std::string::npos) what = what.substr(close + 2);
    fail_input("not a JSON object: " + what, {}, 0, {}, "one object per line, e.g. {\"scene\": \"a.toml\"}");
  }
  if (!obj.is_object()) fail_input("not a JSON object: " + json_brief(obj), {}, 0, {}, "one object per line");
  RenderArgs a = defaults;
  a.output.clear();  // -o names one file; a job names its own
  a.input.clear();
  for (const auto& [key, value] : obj.items()) {
    const auto h = handlers().find(key);
    if (h == handlers().end()) {
      std::vector<std::string_view> names;
      for (const std::string& k : job_keys()) names.push_back(k);
      fail_input("unknown key '" + key + "'", {}, 0, key, did_you_mean(key, names));
    }
    h->second(KeyValue{value, base, key}, a);
  }
  if (a.input.empty()) fail_input("the job has no 'scene'", {}, 0, "scene", "e.g. {\"scene\": \"scenes/seed.toml\"}");
  return make_render_job(a, a.input, a.output.empty() ? default_output(a.input) : fs::path(a.output));
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
    return k;
  }();
  return keys;
}

JobFile::JobFile(const fs::path& file, const RenderArgs& defaults, DefaultOutput default_output)
    : file_(file), defaults_(defaults), default_output_(std::move(default_output)), buf_(std::size_t{1} << 16) {
  // Non-blocking, so that a FIFO named here is refused rather than waited on.
  fd_ = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  struct stat st{};
  if (fd_ >= 0 && ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode)) return;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
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
      e.job = job_from_line(line_, defaults_, file_.parent_path(), default_output_);
      e.job->label = e.label;
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
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
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
