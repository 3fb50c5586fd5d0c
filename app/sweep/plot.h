// The sweep's picture: frame time (log scale) against PSNR, one panel per
// reference (same spp, supersampled), every row a dot, each Pareto front a
// line, the textbook baseline, the presets and the default preset marked.
// Drawn on the image module's canvas (io/image_backend.h: OpenImageIO's
// render_line, render_box, render_text): no plotting dependency. Text needs a TrueType font (DejaVu
// Sans on Debian); without one the plot is drawn without text.
#pragma once
#include <string>

#include "sweep/sweep.h"
#include "io/image.h"

namespace ms {

struct SweepPlot {
  Image image;            // RGB, display values in [0, 1]
  bool has_text = false;  // false: no usable font was found, labels are missing
};

// `title`: the heading (scene and size). Rows with PSNR +inf (identical to
// the reference) are drawn on the top edge with an upward triangle.
SweepPlot plot_sweep(const SweepResult& r, const std::string& title);

}  // namespace ms
