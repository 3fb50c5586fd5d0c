// glslViewer's command-line habits typed at marchstudio: `-w 320 -h 180
// -E out.png` or `--headless`. marchstudio's -h is help, and -w and -E
// mean nothing here, so each is refused in one line that names what to use
// (`--size WxH`, `-o FILE`), exit 2, rather than help with exit 0 and no
// image. `-h` alone, or before anything but a number, is still help.
#pragma once
#include <string>
#include <vector>

namespace ms {

// "" when argv holds none of glslViewer's flags; else the line to print
// after "marchstudio: ".
std::string glslviewer_habit(int argc, char** argv);

// glslViewer binds the images on its command line as u_tex0, u_tex1, ..;
// marchstudio takes them with --texture. Throws bad_input for the first
// input that is an image file (by its extension), before any job runs.
void refuse_image_inputs(const std::vector<std::string>& inputs);

}  // namespace ms
