// Where marchstudio keeps what it can recompute: $XDG_CACHE_HOME/marchstudio,
// else ~/.cache/marchstudio, else a directory of our own in the temporary
// directory ($TMPDIR/marchstudio-<uid>, mode 0700), else none. One home for
// the irradiance cache (render/environment.h), the dispatch choice
// (pipeline/dispatch_probe.h) and pruned grids (render/graph_field_cache.h).
//
// A cache entry is only ever a hint: one that is not a regular file (a FIFO,
// a device, a directory, a link), too large or unreadable is a miss, read
// without ever blocking; one that cannot be written is skipped.
//
//   const fs::path p = cache_dir();              // empty: no cache this run
//   if (!p.empty() && read_cache_file(p / "dispatch", text)) ...
//   write_cache_file(p / "dispatch", text);      // false when it was not written
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace ms {

// The cache's root, or empty when there is none: without HOME and
// XDG_CACHE_HOME the shared temporary directory is used only through a
// directory that is ours alone (made 0700, and checked with lstat to be a
// directory, not a link, owned by us with mode 0700).
std::filesystem::path cache_dir();

// The bytes of a cache entry: false (a miss) unless `path` is a regular
// file of at most `limit` bytes (io/input_file.h open_regular_file: a FIFO
// never waits, and a link is not followed, as the writer never makes one).
// `why` (may be null) gets why an entry that is there was refused, and is
// empty when there is none.
bool read_cache_file(const std::filesystem::path& path, std::string& bytes, std::size_t limit = 1 << 20,
                     std::string* why = nullptr);

// Writes an entry atomically (io/atomic_file.h), its directory made first.
// False, with `why` when given, when it was not written: no cache, a path
// that exists and is not a regular file, or a failed write.
bool write_cache_file(const std::filesystem::path& path, std::string_view bytes, std::string* why = nullptr);

}  // namespace ms
