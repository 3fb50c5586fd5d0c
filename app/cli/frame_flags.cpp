#include "cli/frame_flags.h"

#include <regex>

#include "core/error.h"

namespace ms {

FrameRange parse_frame_range(const std::string& text) {
  static const std::regex re(R"(^\s*(-?\d{1,12})\s*(?:\.\.\s*(-?\d{1,12})\s*)?$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    fail_input("invalid frame range '" + text + "'", {}, 0, "--frames", "expected A..B, e.g. 0..59 (both included)");
  const long long a = std::stoll(m[1]), b = m[2].matched ? std::stoll(m[2]) : a;
  if (a < 0 || b < 0)
    fail_input("frame numbers must not be negative, got '" + text + "'", {}, 0, "--frames", "frames count from 0");
  if (a > kMaxFrame || b > kMaxFrame)
    fail_input("frame number over " + std::to_string(kMaxFrame) + " in '" + text + "'", {}, 0, "--frames");
  if (b < a)
    fail_input("frame range '" + text + "' ends before it starts", {}, 0, "--frames",
               "write the first frame first: " + std::to_string(b) + ".." + std::to_string(a));
  return {static_cast<int>(a), static_cast<int>(b)};
}

Shard parse_shard(const std::string& text) {
  static const std::regex re(R"(^\s*(-?\d{1,9})\s*/\s*(-?\d{1,9})\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re))
    fail_input("invalid shard '" + text + "'", {}, 0, "--shard", "expected I/N with 0 <= I < N, e.g. 0/4");
  const Shard s{std::stoi(m[1]), std::stoi(m[2])};
  if (s.count < 1) fail_input("shard count must be at least 1, got '" + text + "'", {}, 0, "--shard");
  if (s.index < 0 || s.index >= s.count)
    fail_input("shard index must be in 0.." + std::to_string(s.count - 1) + ", got '" + text + "'", {}, 0, "--shard",
               "shards count from 0: 0/" + std::to_string(s.count) + " .. " + std::to_string(s.count - 1) + "/" +
                   std::to_string(s.count));
  return s;
}

ShardMode parse_shard_mode(const std::string& text) {
  if (text == "stride") return ShardMode::stride;
  if (text == "chunk") return ShardMode::chunk;
  fail_input("unknown shard mode '" + text + "'", {}, 0, "--shard-mode", "expected 'stride' or 'chunk'");
}

}  // namespace ms
