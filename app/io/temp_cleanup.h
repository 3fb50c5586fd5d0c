// The temporaries of io/atomic_file.h (".<name>.tmp<pid>" beside the
// target) under signals and reruns, for every still a process writes (one
// image, a --jobs batch, a tiled still) and every mesh (an OBJ with its
// .mtl): one signal scope for all of them.
//
//   for (const fs::path& p : remove_dead_temps({output})) ...   // a killed run's
//   {
//     const RemoveTempOnSignal guard(output);  // before the temporary is made
//     write_image(img, output, meta);          // SIGINT/SIGTERM: removed, exit 130/143
//   }
//
// Only SIGKILL (which nothing can catch) leaves a temporary; the next run
// for the same output removes it once its process is gone. A sequence has
// its own scope (cli/sequence_cmd.cpp): a signal there stops after the frame
// in flight, which is still written.
#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "core/signal_scope.h"

namespace ms {

// For its life, SIGINT and SIGTERM remove `target`'s temporary of this
// process (temp_path_for(target, getpid())) and end the process at once
// with 128 + the signal. The name is kept where the handler can read it
// (async-signal-safe: unlink, _exit). Guards nest (a tiled still inside a
// job's); they belong to one thread, the one that writes.
class RemoveTempOnSignal {
 public:
  // Remove::file: `target` itself instead, for a file this write has just
  // made that means nothing without the rest (an OBJ's new .mtl).
  enum class Remove { temporary, file };
  explicit RemoveTempOnSignal(const std::filesystem::path& target, Remove what = Remove::temporary);
  ~RemoveTempOnSignal();
  RemoveTempOnSignal(const RemoveTempOnSignal&) = delete;
  RemoveTempOnSignal& operator=(const RemoveTempOnSignal&) = delete;

 private:
  int slot_ = -1;
  std::optional<SignalScope> scope_;
};

// Removes the temporaries of `targets` (io/atomic_file.h's is_temp_of)
// whose process is gone: not this one, and no live process has that pid.
// Each directory is read once, however many targets are in it (a batch).
// Returns what it removed.
std::vector<std::filesystem::path> remove_dead_temps(const std::vector<std::filesystem::path>& targets);

}  // namespace ms
