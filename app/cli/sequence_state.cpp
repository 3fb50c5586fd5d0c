#include "cli/sequence_state.h"

#include <cstdio>
#include <system_error>

namespace ms {
namespace fs = std::filesystem;

ResumeScan scan_existing(const FramePattern& pattern, const std::vector<int>& mine, int width, int height,
                         const FrameFingerprint& fingerprint, bool force) {
  for (const fs::path& p : remove_stale_temps(pattern, mine))
    std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted run\n", p.string().c_str());
  ResumeScan scan;
  for (int f : mine) {
    std::string why;
    const fs::path p = pattern.path(f);
    if (force) {
      scan.todo.push_back(f);
      continue;
    }
    if (frame_is_complete(p, width, height, &why, fingerprint(f))) {
      scan.skipped.emplace_back(f, p.string());
      continue;
    }
    scan.todo.push_back(f);
    if (why == kNoFingerprint) scan.unmarked.push_back(f);
    else if (why == kOtherFingerprint) scan.stale.push_back(f);
    else if (why != "missing") scan.redone.emplace_back(f, why);
  }
  return scan;
}

StatefulPlan plan_stateful(const std::vector<int>& mine, const FramePattern& pattern, int width, int height,
                           const std::string& key, const FrameFingerprint& fingerprint, bool fresh) {
  StatefulPlan p;
  p.key = key;
  if (!fresh) {
    std::error_code ec;
    for (int f : mine) {
      if (!frame_is_complete(pattern.path(f), width, height, nullptr, fingerprint(f))) break;
      if (fs::is_regular_file(checkpoint_path(pattern.path(f), key), ec)) p.resume_from = f;
    }
  }
  for (int f : mine)
    if (f > p.resume_from) p.todo.push_back(f);
  p.replay_until = p.resume_from >= 0 || mine.empty() ? 0 : mine.front();
  return p;
}

}  // namespace ms
