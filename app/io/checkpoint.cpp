#include "io/checkpoint.h"

#include <cstdio>

#include "core/error.h"
#include "core/version.h"
#include "io/atomic_file.h"
#include "io/image_backend.h"
#include "io/image_io.h"
#include "io/input_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

const char* kComponents[] = {"R", "G", "B", "A"};

std::string letter(int buffer) { return std::string(1, static_cast<char>('A' + buffer)); }

constexpr int kCube = 4;  // scene/project.h's kCubeA: Shadertoy's Cube A, six faces stacked

}  // namespace

fs::path cube_checkpoint_path(const fs::path& state) {
  std::string name = state.filename().string();
  const std::string tail = ".state.exr";
  if (name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0)
    name.resize(name.size() - tail.size());
  return state.parent_path() / (name + ".cube.state.exr");
}

void remove_checkpoint(const fs::path& state) {
  std::error_code ec;
  fs::remove(state, ec);  // the marker first: a lone cube file is never read
  fs::remove(cube_checkpoint_path(state), ec);
}

fs::path checkpoint_path(const fs::path& frame, const std::string& key) {
  std::string name = ".";  // appended, not "." + name: GCC 12's false -Wrestrict
  name += frame.filename().string();
  name += "." + key + ".state.exr";
  return frame.parent_path() / name;
}

std::string state_key(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

void write_checkpoint(const fs::path& path, const BufferState& all_state, const std::string& fingerprint) {
  if (all_state.empty()) return;
  ImageMetadata meta{{"Software", std::string(kSoftware) + " sequence state"}};
  if (!fingerprint.empty()) add_fingerprint(meta, fingerprint);
  // Cube A beside, written first: the main file marks a complete checkpoint.
  BufferState state;
  for (const auto& entry : all_state)
    if (entry.first == kCube) write_image(entry.second, cube_checkpoint_path(path), meta);
    else state.push_back(entry);
  Image all;
  if (state.empty()) {  // Cube A alone: a one-pixel marker
    all.width = all.height = 1;
    all.channels = {"Cube"};
    all.pixels = {0.0f};
    write_image(all, path, meta);
    return;
  }
  all.width = state.front().second.width;
  all.height = state.front().second.height;
  for (const auto& [b, img] : state)
    for (const char* c : kComponents) all.channels.push_back(letter(b) + "." + c);
  const size_t n = static_cast<size_t>(all.width) * all.height, nc = all.channels.size();
  all.pixels.resize(n * nc);
  for (size_t k = 0; k < state.size(); ++k)
    for (size_t p = 0; p < n; ++p)
      for (int c = 0; c < 4; ++c) all.pixels[p * nc + k * 4 + c] = state[k].second.pixels[p * 4 + c];
  write_image(all, path, meta);
}

namespace {

// One file of a checkpoint, its pixels and its fingerprint, read from one
// copy of its bytes. Throws bad_input (a cut or corrupt file).
Image read_state_file(const fs::path& path, const std::string& fingerprint, std::string& why) {
  const std::string bytes = read_input_file(path, "checkpoint", {}, kMaxImageInput);
  const ImageBackend& codec = image_backend();
  if (!fingerprint.empty() && fingerprint_of(codec.read_info(bytes, path)) != fingerprint) {
    why = "it was made for another frame or run";
    return {};
  }
  return codec.read(bytes, path, false);  // EXR: stored as drawn, associated
}

// read_checkpoint(), with why it is empty in `why`.
BufferState read_checkpoint_checked(const fs::path& path, const std::vector<int>& all_buffers, int width, int height,
                                    const std::string& fingerprint, std::string& why) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    why = "missing";
    return {};
  }
  std::vector<int> buffers;
  for (int b : all_buffers)
    if (b != kCube) buffers.push_back(b);
  Image all, cube;
  try {
    all = read_state_file(path, fingerprint, why);
    if (why.empty() && buffers.size() != all_buffers.size())
      cube = read_state_file(cube_checkpoint_path(path), fingerprint, why);
  } catch (const Error& e) {
    why = "unreadable: " + e.info().what.substr(0, e.info().what.find('\n'));
    return {};  // not a state to resume from
  }
  if (!why.empty()) return {};
  why = "it holds other buffers or another size";
  const bool marker = buffers.empty() && all.nchannels() == 1 && all.channels[0] == "Cube";
  if (!marker && (all.width != width || all.height != height || all.nchannels() != 4 * static_cast<int>(buffers.size())))
    return {};
  const bool with_cube = buffers.size() != all_buffers.size();
  if (with_cube && (cube.channels != std::vector<std::string>{"R", "G", "B", "A"} || cube.height != 6 * cube.width))
    return {};
  BufferState out;
  const size_t n = static_cast<size_t>(width) * height, nc = all.channels.size();
  for (size_t k = 0; k < buffers.size(); ++k) {
    for (int c = 0; c < 4; ++c) {
      // EXR sorts channels by name; look each one up.
      const std::string name = letter(buffers[k]) + "." + kComponents[c];
      bool found = false;
      for (size_t i = 0; i < nc && !found; ++i) found = all.channels[i] == name;
      if (!found) return {};
    }
    Image img;
    img.width = width;
    img.height = height;
    img.channels = {"R", "G", "B", "A"};
    img.pixels.resize(n * 4);
    for (int c = 0; c < 4; ++c) {
      const std::string name = letter(buffers[k]) + "." + kComponents[c];
      size_t i = 0;
      while (all.channels[i] != name) ++i;
      for (size_t p = 0; p < n; ++p) img.pixels[p * 4 + c] = all.pixels[p * nc + i];
    }
    out.emplace_back(buffers[k], std::move(img));
  }
  if (with_cube) out.emplace_back(kCube, std::move(cube));
  why.clear();
  return out;
}

}  // namespace

BufferState read_checkpoint(const fs::path& path, const std::vector<int>& all_buffers, int width, int height,
                            const std::string& fingerprint, std::string* why_not) {
  std::string why;
  BufferState out = read_checkpoint_checked(path, all_buffers, width, height, fingerprint, why);
  if (why_not) *why_not = why;
  return out;
}

std::vector<fs::path> remove_checkpoint_temps(const std::vector<fs::path>& frames, const std::string& key) {
  std::vector<fs::path> removed;
  if (frames.empty()) return removed;
  const fs::path dir = frames.front().parent_path().empty() ? fs::path(".") : frames.front().parent_path();
  std::error_code ec;
  std::vector<fs::path> candidates;  // a checkpoint's temporary starts with ".."
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind("..", 0) == 0) candidates.push_back(e.path());
  for (const fs::path& c : candidates)
    for (const fs::path& f : frames) {
      const fs::path state = checkpoint_path(f, key);
      if (!is_temp_of(c.filename().string(), state) && !is_temp_of(c.filename().string(), cube_checkpoint_path(state)))
        continue;
      if (fs::remove(c, ec)) removed.push_back(frames.front().parent_path() / c.filename());
      break;
    }
  return removed;
}

void remove_checkpoints(const fs::path& frame, const fs::path& keep) {
  const fs::path dir = frame.parent_path().empty() ? fs::path(".") : frame.parent_path();
  std::string prefix = ".";  // appended, not "." + name: GCC 12's false -Wrestrict
  prefix += frame.filename().string();
  prefix += ".";
  std::error_code ec;
  std::vector<fs::path> old;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() > prefix.size() + 10 &&
        name.compare(name.size() - 10, 10, ".state.exr") == 0 && e.path().filename() != keep.filename() &&
        (keep.empty() || e.path().filename() != cube_checkpoint_path(keep).filename()))
      old.push_back(e.path());
  }
  for (const fs::path& p : old) fs::remove(p, ec);
}

}  // namespace ms
