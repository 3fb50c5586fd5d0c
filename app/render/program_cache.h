// Linked programs kept by the hash of their sources (shader/specialize.h,
// program_key), so the viewer does not recompile a shader it has built
// before: toggling a feature off and on again, or back to a debug view, is a
// lookup. Needs the GL context current for get() and for destruction.
#pragma once
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <string>

#include "render/program.h"
#include "preprocess/preprocess.h"

namespace ms {

class ProgramCache {
 public:
  explicit ProgramCache(std::size_t capacity = 16) : capacity_(capacity < 1 ? 1 : capacity) {}

  // The program for these sources: the cached one when the key and the
  // sources match, else a fresh compile and link (which may throw ms::Error,
  // leaving the cache as it was). `hit` reports which. At most `capacity`
  // programs are kept; the least recently used goes first.
  std::shared_ptr<const Program> get(const std::string& vertex, const ShaderSource& fragment, bool* hit = nullptr);

  // Keep a program linked elsewhere (the viewer's compile worker, on a
  // context sharing this one's objects) as get() would have: the next get()
  // of these sources is a hit. The cache itself is for one thread only.
  void put(const std::string& vertex, const ShaderSource& fragment, std::shared_ptr<const Program> program);

  // Whether get() would find these sources without compiling.
  bool contains(const std::string& vertex, const ShaderSource& fragment) const;
  std::size_t size() const { return entries_.size(); }
  long hits() const { return hits_; }
  long misses() const { return misses_; }
  void clear() { entries_.clear(); }  // with the context current

 private:
  struct Entry {
    std::uint64_t key = 0;
    std::string vertex, fragment;  // compared too: a 64-bit collision must not swap programs
    std::shared_ptr<const Program> program;
  };
  std::size_t capacity_;
  std::list<Entry> entries_;  // most recently used first
  long hits_ = 0, misses_ = 0;
};

}  // namespace ms
