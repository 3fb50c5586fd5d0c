// Pictures out of the viewer besides FrameRenderer::render() (the frame
// screenshot, which goes through the same path as `render`): a grab of the
// window itself with the panel on it, and screenshot file names.
#pragma once
#include <filesystem>
#include <string>

#include "io/image.h"

namespace ms::live {

// The current back buffer of the window (call after drawing the UI, before
// the swap), as RGB, top row first.
Image grab_window(int fb_width, int fb_height);

// `dir`/`stem`_`n`.png for the first n >= 1 that does not exist yet;
// creates `dir` when it is missing.
std::filesystem::path next_free_path(const std::filesystem::path& dir, const std::string& stem);

}  // namespace ms::live
