#include "pipeline/sequence_state.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include "scene/project.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Resumes after frame `from` (-1: from the start, replaying the frames
// before this run's first).
void resume_at(StatefulPlan& p, const std::vector<int>& mine, int from) {
  p.resume_from = from;
  p.todo.clear();
  for (int f : mine)
    if (f > from) p.todo.push_back(f);
  p.replay_until = from >= 0 || mine.empty() ? 0 : mine.front();
}

}  // namespace

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
      if (fs::is_regular_file(checkpoint_path(pattern.path(f), key), ec)) p.candidates.push_back(f);
    }
  }
  resume_at(p, mine, p.candidates.empty() ? -1 : p.candidates.back());
  return p;
}

void load_resume_state(StatefulPlan& p, const std::vector<int>& mine, const FramePattern& pattern,
                       const std::vector<int>& buffers, int width, int height, const FrameFingerprint& fingerprint) {
  while (!p.candidates.empty()) {
    const int f = p.candidates.back();
    p.candidates.pop_back();
    const fs::path path = checkpoint_path(pattern.path(f), p.key);
    std::string why;
    p.state = read_checkpoint(path, buffers, width, height, fingerprint(f), &why);
    if (p.state.size() == buffers.size() && !buffers.empty()) {
      resume_at(p, mine, f);
      return;
    }
    p.state.clear();
    std::fprintf(stderr, "marchstudio: %s: warning: the checkpoint of frame %d is not used (%s): %s\n",
                 path.string().c_str(), f, why.c_str(),
                 p.candidates.empty() ? "the frames render again from the start"
                                      : "trying the one before it");
  }
  resume_at(p, mine, -1);
}

void remove_checkpoint_temps(const FramePattern& pattern, const std::vector<int>& mine, const std::string& key) {
  std::vector<fs::path> frames;
  for (int f : mine) frames.push_back(pattern.path(f));
  for (const fs::path& p : remove_checkpoint_temps(frames, key))
    std::fprintf(stderr, "marchstudio: removed %s, left by an interrupted run\n", p.string().c_str());
}

std::vector<int> state_buffers(const std::vector<PassSource>& passes) {
  std::vector<int> out;
  for (int b = 0; b < 4; ++b)
    if (std::any_of(passes.begin(), passes.end(), [b](const PassSource& s) { return s.output == b; })) out.push_back(b);
  if (std::any_of(passes.begin(), passes.end(), [](const PassSource& s) { return s.output == kCubeA; }))
    out.push_back(kCubeA);
  return out;
}

}  // namespace ms
