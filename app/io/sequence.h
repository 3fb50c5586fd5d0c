// Image sequences on disk: which frames to render (a range, split into
// shards), where each frame goes (a printf-style pattern such as
// out/frame_%04d.png), and which frames a rerun can skip (complete files
// already there). No GL here; app/cli/sequence_cmd.cpp drives it.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

// The largest frame number: eight digits keep frame arithmetic far from
// int overflow, and at 60 fps that is over two weeks of animation.
inline constexpr int kMaxFrame = 99'999'999;

// Frames first..last, both included, 0 <= first <= last <= kMaxFrame.
// (--frames' text is cli/frame_flags.h's; a suite file's is suite/'s.)
struct FrameRange {
  int first = 0;
  int last = 0;
  int count() const { return last - first + 1; }
};

// One of `count` independent processes; `index` counts from 0 (--shard I/N).
struct Shard {
  int index = 0;
  int count = 1;
};

// stride: frames first+I, first+I+N, ... (every shard sees the whole time
// range, so a partial run already shows the entire animation coarsely);
// chunk: the I-th of N contiguous runs, sizes differing by at most one (a
// shard's frames stay together, for tools that want one contiguous clip).
enum class ShardMode { stride, chunk };

// The frames shard `s` renders, ascending. Over all s.index in [0, s.count)
// the lists partition the range: every frame exactly once. Empty when a
// shard has nothing to do (more shards than frames).
std::vector<int> shard_frames(FrameRange range, Shard s, ShardMode mode);

// An output pattern: exactly one %d or %0Nd field (N <= 12) in the file
// name, "%%" for a literal '%', as printf and ffmpeg read it. (%Nd is
// refused: printf pads it with spaces, ffmpeg with zeros.)
class FramePattern {
 public:
  // Throws bad_input (key -o) when the pattern has no field, more than one,
  // a field in a directory name, or another '%' sequence.
  explicit FramePattern(const std::string& pattern);
  const std::string& text() const { return text_; }
  std::filesystem::path path(int frame) const;

 private:
  std::string text_, prefix_, suffix_;  // prefix_ and suffix_ with "%%" already made '%'
  int width_ = 0;
  bool zero_pad_ = false;
};

// True when `text` contains a frame field (any '%' that is not "%%").
bool has_frame_field(const std::string& text);

// Does `path` hold a complete image of width x height? It must open, have
// that size, decode to the last pixel and, when `fingerprint` is given,
// carry that fingerprint (io/image_io.h): a frame made from other inputs or
// settings is not this run's. `why` (may be null) gets the reason when not,
// e.g. "640x360 expected, file is 320x180".
bool frame_is_complete(const std::filesystem::path& path, int width, int height, std::string* why = nullptr,
                       std::string_view fingerprint = {});
// The two `why`s of a complete frame that is not this run's.
inline constexpr const char* kNoFingerprint = "it has no marchstudio fingerprint";
inline constexpr const char* kOtherFingerprint = "it was made from other inputs or settings (its fingerprint differs)";

// Remove the temporaries that write_image leaves when its process is
// killed (".<stem>.tmp<pid><ext>" beside the frame) for `frames` only, so
// that shards sharing a directory never touch each other's files. Returns
// the paths removed.
std::vector<std::filesystem::path> remove_stale_temps(const FramePattern& pattern, const std::vector<int>& frames);

}  // namespace ms
