// The text of --frames, --shard and --shard-mode made into io/sequence.h's
// typed values, once, here: nothing below cli/ reads this syntax.
#pragma once
#include <string>

#include "io/sequence.h"

namespace ms {

// "A..B" (or "A" for one frame). Throws bad_input (key --frames) for
// malformed text, negative numbers, B < A or numbers over kMaxFrame.
FrameRange parse_frame_range(const std::string& text);

// "I/N" with 0 <= I < N. Throws bad_input (key --shard).
Shard parse_shard(const std::string& text);

// "stride" | "chunk". Throws bad_input (key --shard-mode).
ShardMode parse_shard_mode(const std::string& text);

}  // namespace ms
