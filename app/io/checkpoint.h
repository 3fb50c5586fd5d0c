// The state of a sequence of a shader with buffers, saved beside each frame
// it goes with, so a killed sequence resumes with bit-identical frames: the
// buffers' float RGBA pixels in one lossless EXR (channels A.R .. D.A),
// written atomically by the frame's writer after the frame itself.
//
//   write_checkpoint(checkpoint_path(frame_path, key), {{0, a}, {2, c}}, fingerprint);
//   auto state = read_checkpoint(path, buffers, w, h, fingerprint, &why);  // empty: why not
//
// Shadertoy's Cube A (index 4, scene/project.h's kCubeA; six faces stacked,
// not the image's size) goes in a second file beside it,
// ".<frame file name>.<key>.cube.state.exr", written before the main file,
// which marks the checkpoint complete; with Cube A alone the main file is a
// one-pixel marker.
//
// `key` says what made the state (the passes' sources, size, fps, mouse): a
// checkpoint of another shader or size has another name and is never read.
// Each file also carries its frame's fingerprint (pipeline/fingerprint.h: the
// run and the frame number), checked on reading: a checkpoint copied over
// another frame's, or left by another run under the same name, is not
// trusted.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/image.h"

namespace ms {

using BufferState = std::vector<std::pair<int, Image>>;  // buffer index (0..3 for A..D, 4 Cube A), its RGBA pixels

// ".<frame file name>.<key>.state.exr" beside the frame.
std::filesystem::path checkpoint_path(const std::filesystem::path& frame, const std::string& key);

// A short hex key of `text` (FNV-1a, 64 bits).
std::string state_key(const std::string& text);

// `fingerprint`: the frame's, written into both files (none when empty).
void write_checkpoint(const std::filesystem::path& path, const BufferState& state, const std::string& fingerprint = {});

// The buffers of `path`, each width x height; empty, with why in `why`,
// when the file is missing, cannot be decoded, does not carry
// `fingerprint` (when one is given) or does not hold exactly `buffers` at
// that size. Never throws for a bad file.
BufferState read_checkpoint(const std::filesystem::path& path, const std::vector<int>& buffers, int width, int height,
                            const std::string& fingerprint = {}, std::string* why = nullptr);

// The Cube A file that goes with the checkpoint `state`.
std::filesystem::path cube_checkpoint_path(const std::filesystem::path& state);
// Removes one checkpoint, its Cube A file included.
void remove_checkpoint(const std::filesystem::path& state);

// Removes the temporaries (io/atomic_file.h) of the checkpoints with `key`
// of `frames` (all in one directory) that a killed run left; returns them.
std::vector<std::filesystem::path> remove_checkpoint_temps(const std::vector<std::filesystem::path>& frames,
                                                           const std::string& key);

// Removes the checkpoints of `frame` whatever their key, but `keep` (and its Cube A file).
void remove_checkpoints(const std::filesystem::path& frame, const std::filesystem::path& keep = {});

}  // namespace ms
