#include "render/graph_field_cache.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include "core/hash.h"
#include "core/version.h"
#include "io/cache_dir.h"

namespace ms {

namespace {

// The version is in the magic: an entry of an older layout is a miss.
constexpr char kMagic[8] = {'M', 'S', 'P', 'R', 'U', 'N', 'E', '2'};
constexpr std::size_t kLimit = std::size_t{512} << 20;
constexpr std::size_t kHex = 32;
// Magic, key, bytes kept of the three buffers and the pool's base, content hash.
constexpr std::size_t kHeader = sizeof kMagic + kHex + 4 * sizeof(std::uint64_t) + kHex;

const char* gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

// The fields between the magic and the hash, as written.
struct Fields {
  std::string key;
  std::uint64_t kept[3] = {0, 0, 0};
  std::uint64_t pool_base = 0;
};

// What the hash covers: every field but the magic, and the body.
std::string content_hash(const Fields& f, std::string_view body) {
  Hash128 h;
  h.add(f.key);
  for (std::uint64_t k : f.kept) h.add(static_cast<std::int64_t>(k));
  h.add(static_cast<std::int64_t>(f.pool_base)).add(body);
  return h.hex();
}

std::uint64_t u64_at(const std::string& data, std::size_t at) {
  std::uint64_t v = 0;
  std::memcpy(&v, data.data() + at, sizeof v);
  return v;
}

// The bytes of the first buffer in use: up to the pool's base and the
// words of the pool that the coarse buffer's first word counts.
std::uint64_t first_kept(std::uint32_t used, const PrunedSizes& s) {
  return std::min<std::uint64_t>(s.bytes[0], s.pool_base + std::uint64_t{used} * sizeof used);
}

// The fields of an entry's header (the magic checked first).
bool read_fields(const std::string& data, Fields& f) {
  if (data.size() < kHeader || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0) return false;
  f.key.assign(data, sizeof kMagic, kHex);
  const std::size_t at = sizeof kMagic + kHex;
  for (int i = 0; i < 3; ++i) f.kept[i] = u64_at(data, at + 8 * i);
  f.pool_base = u64_at(data, at + 24);
  return true;
}

// Why `data` is not an entry for this plan under `key`; empty when it is one.
std::string entry_problem(const std::string& data, const std::string& key, const PrunedSizes& s) {
  Fields f;
  if (!read_fields(data, f)) return "is not a pruned grid of this version";
  if (f.key != key) return "holds another key";
  if (f.kept[1] != s.bytes[1] || f.kept[2] != s.bytes[2] || f.pool_base != s.pool_base || f.kept[0] < s.pool_base ||
      f.kept[0] > s.bytes[0] || (f.kept[0] - s.pool_base) % sizeof(std::uint32_t) != 0)
    return "has a header that does not fit this graph's plan";
  const std::uint64_t body = f.kept[0] + f.kept[1] + f.kept[2];  // no overflow: each is bounded above
  if (data.size() - kHeader != body)
    return "is " + std::to_string(data.size()) + " bytes, its header says " + std::to_string(kHeader + body);
  const std::string_view all(data);
  if (content_hash(f, all.substr(kHeader)) != all.substr(kHeader - kHex, kHex))
    return "differs from what was written (content hash)";
  std::uint32_t used = 0;
  if (f.kept[2] >= sizeof used) std::memcpy(&used, data.data() + kHeader + f.kept[0] + f.kept[1], sizeof used);
  if (f.kept[0] != first_kept(used, s)) return "has a pool count that disagrees with its lists";
  return {};
}

}  // namespace

double prune_cache_ms() {
  const char* v = std::getenv("MARCH_PRUNE_CACHE_MS");
  char* end = nullptr;
  const double ms = v ? std::strtod(v, &end) : 0.0;
  return v && end != v && *end == '\0' && ms >= 0.0 ? ms : 300.0;
}

PrunedCache::PrunedCache(const GraphBuffers& b, const GraphEvalPlan& plan, const std::string& prune_source) {
  if (prune_source.empty() || !plan.pruned()) return;
  const std::filesystem::path dir = cache_dir();
  if (dir.empty()) return;
  Hash128 h;
  h.add(kSoftware).add(prune_source).add(gl_string(GL_RENDERER)).add(gl_string(GL_VERSION));
  const auto words = [&h](const auto& v) {
    h.add(std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(v[0])));
  };
  words(b.nodes);
  words(b.floats);
  words(b.program);
  words(grid_header(plan, b));
  h.add(static_cast<std::int64_t>(plan.pool));
  path_ = dir / "pruned" / (h.hex() + ".bin");
}

bool PrunedCache::load(const GLuint buffers[3], const PrunedSizes& sizes, std::string* refused) const {
  std::string data, why;
  if (refused) refused->clear();
  if (path_.empty()) return false;
  if (read_cache_file(path_, data, kLimit, &why)) why = entry_problem(data, path_.stem().string(), sizes);
  else if (why.empty()) return false;  // no entry
  if (!why.empty()) {
    if (refused) *refused = why;
    return false;
  }
  Fields f;
  read_fields(data, f);
  std::size_t at = kHeader;
  for (int i = 0; i < 3; ++i) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[i]);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(f.kept[i]), data.data() + at);
    at += static_cast<std::size_t>(f.kept[i]);
  }
  return true;
}

bool PrunedCache::save(const GLuint buffers[3], const PrunedSizes& sizes) const {
  if (path_.empty()) return false;
  std::uint32_t used = 0;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[2]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof used, &used);
  Fields f;
  f.key = path_.stem().string();
  f.kept[0] = first_kept(used, sizes);
  f.kept[1] = sizes.bytes[1];
  f.kept[2] = sizes.bytes[2];
  f.pool_base = sizes.pool_base;
  const std::uint64_t body = f.kept[0] + f.kept[1] + f.kept[2];
  if (kHeader + body > kLimit) return false;
  std::string data(kMagic, sizeof kMagic);
  data.reserve(static_cast<std::size_t>(kHeader + body));
  data += f.key;
  for (std::uint64_t v : {f.kept[0], f.kept[1], f.kept[2], f.pool_base})
    data.append(reinterpret_cast<const char*>(&v), sizeof v);
  data.resize(static_cast<std::size_t>(kHeader + body));  // the hash's place, then the body
  std::size_t at = kHeader;
  for (int i = 0; i < 3; ++i) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[i]);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(f.kept[i]), data.data() + at);
    at += static_cast<std::size_t>(f.kept[i]);
  }
  const std::string hash = content_hash(f, std::string_view(data).substr(kHeader));
  data.replace(kHeader - kHex, kHex, hash);
  return write_cache_file(path_, data);
}

}  // namespace ms
