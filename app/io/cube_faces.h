// A cubemap input's six faces on the CPU, before any GL (render/cubemap.h
// uploads them): read from Shadertoy's six files or made from one
// equirectangular image. Faces are in GL's (and Shadertoy's) order +X, -X,
// +Y, -Y, +Z, -Z; each is stored top row first, as a file is, and its top
// row is the cube's t = 0 row (GL's face conventions, docs/shadertoy.md#cubemaps).
//
//   auto files = cube_face_files("/m/abc.png");   // abc.png, abc_1.png .. abc_5.png
//   CubeFaces c = read_cube_faces(files);         // square, all one size, or bad_input naming the file
//   CubeFaces e = equirect_to_cube(read_image("sky.exr"), 0);   // face size: width / 4
#pragma once
#include <array>
#include <filesystem>
#include <string>

#include "io/image.h"

namespace ms {

struct CubeFaces {
  int size = 0;                 // each face is size x size
  bool eight_bit = true;        // uploaded as RGBA8 (PNG, JPEG) or float (EXR, HDR)
  std::array<Image, 6> faces;   // +X, -X, +Y, -Y, +Z, -Z; RGBA, top row first
};

// Shadertoy's naming: face 0 is the file itself, face i (1..5) the same
// name with "_i" before the extension ("/media/a/<hash>.jpg", "<hash>_1.jpg").
std::array<std::filesystem::path, 6> cube_face_files(const std::filesystem::path& first);

// The VS Code extension's wildcard: "sky_{}.png" names sky_px.png,
// sky_nx.png .. sky_nz.png (its first "{}" replaced). Empty paths when
// `pattern` has none.
std::array<std::filesystem::path, 6> cube_wildcard_files(const std::string& pattern);

// The six files as faces. Throws bad_input naming the file for one that
// cannot be read, is not square, or differs in size from face 0, and
// naming face 0 when six of its size are over the memory budget.
CubeFaces read_cube_faces(const std::array<std::filesystem::path, 6>& files);

// The unit direction through point (s, t) in [0, 1]^2 of `face` (0..5):
// GL's cube map table read backwards (OpenGL 4.6, table 8.19), which is
// also Shadertoy's Cube A corners. t = 0 is a face's first (top) row.
void cube_face_direction(int face, float s, float t, float dir[3]);

// An equirectangular (latitude-longitude) image as six faces of `size`
// (0: width / 4, at least 1), bilinear, wrapping in longitude. Pixel (u, v)
// of the image, u = x / width, v = y / height from the top row, looks along
// (-cos(lat) sin(lon), sin(lat), cos(lat) cos(lon)) with lon = 2 pi u and
// lat = pi (1/2 - v): the middle of the image is -Z, its left edge +Z, a
// quarter in -X, its top row +Y (the longitude of Shadertoy's own Cube A
// to equirectangular export, with the picture's top row up). Six faces
// over the memory budget (core/memory_budget.h) are bad_input naming
// `file`, before any is made.
CubeFaces equirect_to_cube(const Image& equirect, int size = 0, const std::string& file = {});

}  // namespace ms
