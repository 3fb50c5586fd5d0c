#include "render/program_cache.h"

#include "shader/specialize.h"

namespace ms {

std::shared_ptr<const Program> ProgramCache::get(const std::string& vertex, const ShaderSource& fragment, bool* hit) {
  const std::uint64_t key = program_key(vertex, fragment.text);
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->key != key || it->vertex != vertex || it->fragment != fragment.text) continue;
    entries_.splice(entries_.begin(), entries_, it);  // now the most recent
    ++hits_;
    if (hit) *hit = true;
    return entries_.front().program;
  }
  auto program = std::make_shared<const Program>(vertex, fragment);  // throws on a compile error
  ++misses_;
  if (hit) *hit = false;
  entries_.push_front(Entry{key, vertex, fragment.text, program});
  if (entries_.size() > capacity_) entries_.pop_back();  // a caller may still hold it: shared_ptr
  return program;
}

void ProgramCache::put(const std::string& vertex, const ShaderSource& fragment, std::shared_ptr<const Program> program) {
  if (contains(vertex, fragment)) return;
  ++misses_;  // compiled, if not here
  entries_.push_front(Entry{program_key(vertex, fragment.text), vertex, fragment.text, std::move(program)});
  if (entries_.size() > capacity_) entries_.pop_back();
}

bool ProgramCache::contains(const std::string& vertex, const ShaderSource& fragment) const {
  const std::uint64_t key = program_key(vertex, fragment.text);
  for (const Entry& e : entries_)
    if (e.key == key && e.vertex == vertex && e.fragment == fragment.text) return true;
  return false;
}

}  // namespace ms
