// LDR-FLIP: the perceptual difference of two display images, after
// Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images" (HPG 2020),
// implemented from the paper: a colour pipeline (contrast sensitivity
// filters in YCxCz, Hunt-adjusted L*a*b*, HyAB distance, redistributed to
// [0, 1]) and a feature pipeline (edges and points of the achromatic
// channel), combined per pixel as dE_c^(1 - dE_f). Pure: pixels in, numbers out.
//
//   FlipMap f = flip_ldr(reference, test);   // f.mean in [0, 1]; 0 = identical
#pragma once
#include <vector>

#include "io/image.h"

namespace ms {

// Pixels per degree of visual angle for a 0.7 m wide 3840-pixel monitor seen
// from 0.7 m, the paper's default observer (about 67 ppd).
double flip_default_ppd();

struct FlipMap {
  int width = 0, height = 0;
  std::vector<float> error;  // per pixel, top row first, in [0, 1]
  double mean = 0.0, max = 0.0;
};

// The first three channels of each image are sRGB-encoded display values,
// clamped to [0, 1] (8-bit files read as they are). Both images must have
// the same size and at least three channels (throws bad_input otherwise).
FlipMap flip_ldr(const Image& reference, const Image& test, double pixels_per_degree = flip_default_ppd());

}  // namespace ms
