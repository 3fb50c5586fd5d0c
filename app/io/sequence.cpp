#include "io/sequence.h"

#include "io/image_io.h"

#include "io/image_backend.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

std::vector<int> shard_frames(FrameRange range, Shard s, ShardMode mode) {
  std::vector<int> out;
  const long long n = range.count();
  if (mode == ShardMode::stride) {
    for (long long f = range.first + s.index; f <= range.last; f += s.count) out.push_back(static_cast<int>(f));
    return out;
  }
  // Chunk i is [i*n/N, (i+1)*n/N): sizes differ by at most one, none overlap.
  const long long begin = s.index * n / s.count, end = (s.index + 1LL) * n / s.count;
  for (long long k = begin; k < end; ++k) out.push_back(static_cast<int>(range.first + k));
  return out;
}

bool has_frame_field(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') continue;
    if (i + 1 < text.size() && text[i + 1] == '%') ++i;
    else return true;
  }
  return false;
}

FramePattern::FramePattern(const std::string& pattern) : text_(pattern) {
  const std::size_t slash = pattern.find_last_of('/');
  const std::size_t name_start = slash == std::string::npos ? 0 : slash + 1;
  const auto bad = [&](const std::string& what, const std::string& hint) {
    fail_input(what, pattern, 0, "-o", hint);
  };
  bool found = false;
  std::string* part = &prefix_;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      *part += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      *part += '%';
      ++i;
      continue;
    }
    // %[0][N]d
    std::size_t j = i + 1;
    const bool zero = j < pattern.size() && pattern[j] == '0';
    if (zero) ++j;
    std::size_t digits = 0;
    int width = 0;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && digits < 3)
      width = width * 10 + (pattern[j++] - '0'), ++digits;
    // printf pads %4d with spaces, ffmpeg with zeros: only %0Nd is unambiguous.
    if (j >= pattern.size() || pattern[j] != 'd' || width > 12 || (digits > 0 && !zero))
      bad("unsupported '%' sequence in the output pattern", "use one %d or %04d for the frame number, %% for '%'");
    if (found) bad("the output pattern has more than one frame field", "use exactly one %d or %04d");
    if (i < name_start)
      bad("the frame field must be in the file name, not a directory", "e.g. out/frame_%04d.png");
    found = true;
    zero_pad_ = zero;
    width_ = width;
    part = &suffix_;
    i = j;
  }
  if (!found)
    bad("the output pattern has no frame field", "with --frames, -o needs %d or %04d, e.g. out/frame_%04d.png");
}

fs::path FramePattern::path(int frame) const {
  std::string num = std::to_string(frame);
  if (static_cast<int>(num.size()) < width_) num.insert(0, static_cast<std::size_t>(width_) - num.size(), zero_pad_ ? '0' : ' ');
  return fs::path(prefix_ + num + suffix_);
}

bool frame_is_complete(const fs::path& path, int width, int height, std::string* why, std::string_view fingerprint) {
  // OpenImageIO's messages can span lines; the log keeps one line per event.
  const auto no = [&](std::string reason) {
    if (why) *why = reason.substr(0, reason.find('\n'));
    return false;
  };
  const std::string problem = input_file_problem(path);
  if (problem == "not found") return no("missing");
  if (!problem.empty()) return no("it " + problem);
  std::string bytes;
  try {
    bytes = read_input_file(path, "frame", {}, kMaxImageInput);
  } catch (const Error& e) {
    return no(e.info().what);
  }
  // Decoding every pixel is what catches a file cut short by something
  // other than our atomic writer (a copy, a full disk); a few ms per frame.
  const ImageBackend& codec = image_backend();
  if (std::string bad = codec.decode_problem(bytes, path); !bad.empty()) return no(bad);
  const ImageInfo info = codec.read_info(bytes, path);
  if (info.width != width || info.height != height)
    return no(std::to_string(width) + "x" + std::to_string(height) + " expected, file is " +
              std::to_string(info.width) + "x" + std::to_string(info.height));
  if (!fingerprint.empty()) {
    const std::string has = fingerprint_of(info);
    if (has.empty()) return no(kNoFingerprint);
    if (has != fingerprint) return no(kOtherFingerprint);
  }
  return true;
}

std::vector<fs::path> remove_stale_temps(const FramePattern& pattern, const std::vector<int>& frames) {
  std::vector<fs::path> removed;
  if (frames.empty()) return removed;
  const fs::path dir = pattern.path(frames.front()).parent_path();
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec);
  if (ec) return removed;
  // Temporaries start with '.': only those are matched against the frames.
  std::vector<fs::path> candidates;
  for (const fs::directory_entry& e : it)
    if (e.path().filename().string().rfind(".", 0) == 0) candidates.push_back(e.path());
  for (const fs::path& c : candidates) {
    const std::string name = c.filename().string();
    for (int f : frames) {
      if (!is_temp_of(name, pattern.path(f))) continue;
      if (fs::remove(c, ec)) removed.push_back(dir / name);
      break;
    }
  }
  return removed;
}

}  // namespace ms
