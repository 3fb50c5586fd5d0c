#include "io/file_stamp.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/hash.h"
#include "io/atomic_file.h"
#include "io/cache_dir.h"
#include "io/input_file.h"
#include "io/json_doc.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

constexpr const char* kSchema = "marchstudio.stamp/1";
// A stamp lists a few names and hashes; anything larger is not one of ours.
constexpr std::uintmax_t kMaxStampBytes = 64 * 1024;

struct Part {
  std::string name;
  std::uintmax_t bytes = 0;
  std::string hash;
};

// Size and content hash of `path`; false, with `why`, when it is not a
// regular file (opened without blocking: a FIFO in a frame's place never
// waits for a writer) or cannot be read whole.
bool measure(const fs::path& path, Part& out, std::string& why) {
  const int fd = open_regular_file(path, why);
  if (fd < 0) return false;
  Hash128 h;
  std::vector<char> buf(std::size_t{1} << 16);
  std::uintmax_t n = 0;
  ssize_t got = 0;
  while ((got = ::read(fd, buf.data(), buf.size())) != 0) {
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) break;
    h.add_bytes(buf.data(), static_cast<std::size_t>(got));
    n += static_cast<std::uintmax_t>(got);
  }
  if (got < 0) why = std::string("cannot be read: ") + std::strerror(errno);
  ::close(fd);
  out.name = path.filename().string();
  out.bytes = n;
  out.hash = h.hex();
  return got == 0;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", c);
      out += esc;
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

fs::path stamp_path(const fs::path& file) {
  return file.parent_path() / ("." + file.filename().string() + ".stamp.json");
}

void write_stamp(const fs::path& file, const std::vector<fs::path>& parts, const std::string& fingerprint) {
  std::string text = "{\"schema\": \"" + std::string(kSchema) + "\", \"fingerprint\": " + json_string(fingerprint) +
                     ", \"files\": [";
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part p;
    std::string why;
    if (!measure(parts[i], p, why)) fail_system("cannot read back what was just written: it " + why, parts[i].string());
    text += (i ? ", " : "") + std::string("{\"name\": ") + json_string(p.name) + ", \"bytes\": " + std::to_string(p.bytes) +
            ", \"hash\": \"" + p.hash + "\"}";
  }
  write_file_atomic(stamp_path(file), text + "]}\n");
}

StampCheck check_stamp(const fs::path& file, const std::vector<fs::path>& parts, const std::string& fingerprint,
                       std::string* why) {
  const auto say = [why](StampCheck c, const std::string& text) {
    if (why) *why = text;
    return c;
  };
  std::error_code ec;
  if (!fs::exists(file, ec)) return StampCheck::missing;
  const fs::path stamp = stamp_path(file);
  // Read as a cache entry is: a hint that is there whole or not at all.
  std::string text, problem;
  if (!read_cache_file(stamp, text, kMaxStampBytes, &problem))
    return say(StampCheck::unmarked, problem.empty() ? "it has no stamp (" + stamp.filename().string() + ")"
                                                     : "its stamp " + stamp.filename().string() + " " + problem);
  JsonDoc doc;
  try {
    doc = parse_json_doc(text, stamp.string());
  } catch (const Error&) {
    return say(StampCheck::unmarked, "its stamp cannot be read");
  }
  const int schema = doc.member(0, "schema"), fp = doc.member(0, "fingerprint"), files = doc.member(0, "files");
  if (schema < 0 || doc.text(schema) != kSchema || fp < 0 || files < 0 || doc.at(files).kind != JsonKind::array)
    return say(StampCheck::unmarked, "its stamp cannot be read");
  if (doc.at(files).count != static_cast<int>(parts.size()))
    return say(StampCheck::damaged, "its stamp lists other files");
  int entry = doc.at(files).first;
  for (const fs::path& part : parts) {
    const JsonValue& e = doc.at(entry);
    const int name = doc.member(entry, "name"), bytes = doc.member(entry, "bytes"), hash = doc.member(entry, "hash");
    entry = e.next;
    if (name < 0 || bytes < 0 || hash < 0 || doc.text(name) != part.filename().string())
      return say(StampCheck::damaged, "its stamp lists other files");
    Part now;
    std::string problem;
    if (!measure(part, now, problem)) return say(StampCheck::damaged, part.filename().string() + " " + problem);
    if (static_cast<double>(now.bytes) != doc.at(bytes).number)
      return say(StampCheck::damaged, part.filename().string() + " has " + std::to_string(now.bytes) + " bytes, " +
                                          std::to_string(static_cast<long long>(doc.at(bytes).number)) + " stamped");
    if (now.hash != doc.text(hash))
      return say(StampCheck::damaged, part.filename().string() + " differs from what was written");
  }
  if (doc.text(fp) != fingerprint)
    return say(StampCheck::other_fingerprint, "its fingerprint differs: made from other inputs or settings");
  return StampCheck::complete;
}

void remove_stamp(const fs::path& file) {
  std::error_code ec;
  fs::remove(stamp_path(file), ec);
}

}  // namespace ms
