#include "cli/sequence_state.h"

#include <system_error>

namespace ms {
namespace fs = std::filesystem;

StatefulPlan plan_stateful(const std::vector<int>& mine, const FramePattern& pattern, int width, int height,
                           const std::string& key, bool no_write) {
  StatefulPlan p;
  p.key = key;
  if (!no_write) {
    std::error_code ec;
    for (int f : mine) {
      if (!frame_is_complete(pattern.path(f), width, height)) break;
      if (fs::is_regular_file(checkpoint_path(pattern.path(f), key), ec)) p.resume_from = f;
    }
  }
  for (int f : mine)
    if (f > p.resume_from) p.todo.push_back(f);
  p.replay_until = p.resume_from >= 0 || mine.empty() ? 0 : mine.front();
  return p;
}

}  // namespace ms
