#include "render/graph_field_cache.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/hash.h"
#include "core/version.h"
#include "io/cache_dir.h"

namespace ms {

namespace {

constexpr char kMagic[8] = {'M', 'S', 'P', 'R', 'U', 'N', 'E', '1'};
constexpr std::size_t kLimit = std::size_t{512} << 20;

const char* gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
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

bool PrunedCache::load(const GLuint buffers[3], const std::size_t bytes[3]) const {
  std::string data;
  if (path_.empty() || !read_cache_file(path_, data, kLimit)) return false;
  std::uint64_t first = 0;
  if (data.size() < sizeof kMagic + sizeof first || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0) return false;
  std::memcpy(&first, data.data() + sizeof kMagic, sizeof first);
  const std::size_t kept[3] = {static_cast<std::size_t>(first), bytes[1], bytes[2]};
  if (first > bytes[0] || data.size() != sizeof kMagic + sizeof first + kept[0] + kept[1] + kept[2]) return false;
  std::size_t at = sizeof kMagic + sizeof first;
  for (int i = 0; i < 3; ++i) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[i]);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(kept[i]), data.data() + at);
    at += kept[i];
  }
  return true;
}

void PrunedCache::save(const GLuint buffers[3], const std::size_t bytes[3], std::size_t pool_base) const {
  if (path_.empty()) return;
  std::uint32_t used = 0;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[2]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof used, &used);
  const std::uint64_t first = std::min<std::uint64_t>(bytes[0], pool_base + std::uint64_t{used} * sizeof used);
  const std::size_t kept[3] = {static_cast<std::size_t>(first), bytes[1], bytes[2]};
  if (sizeof kMagic + sizeof first + kept[0] + kept[1] + kept[2] > kLimit) return;
  std::string data(kMagic, sizeof kMagic);
  data.append(reinterpret_cast<const char*>(&first), sizeof first);
  for (int i = 0; i < 3; ++i) {
    const std::size_t at = data.size();
    data.resize(at + kept[i]);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[i]);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(kept[i]), data.data() + at);
  }
  write_cache_file(path_, data);  // a hint: a failed write is no error
}

}  // namespace ms
