// glslViewer's command-line habits typed at marchstudio: `-w 320 -h 180
// -E out.png` or `--headless`. marchstudio's -h is help, and -w and -E
// mean nothing here, so each is refused in one line that names what to use
// (`--size WxH`, `-o FILE`), exit 2, rather than help with exit 0 and no
// image. `-h` alone, or before anything but a number, is still help.
// A shader named alone (`marchstudio waves.frag`) opens in the viewer, as
// `glslViewer waves.frag` does.
#pragma once
#include <string>
#include <vector>

namespace ms {

// "" when argv holds none of glslViewer's flags; else the line to print
// after "marchstudio: ".
std::string glslviewer_habit(int argc, char** argv);

// A name with the extension of a scene or shader input: .toml, .glsl,
// .frag, .fs or .json (which of them a .glsl is, its text decides).
bool is_input_name(const std::string& arg);

// True when `arg`, in a subcommand's place, is such a file and exists:
// it is then opened as `view arg` is.
bool opens_in_viewer(const std::string& arg);

// glslViewer binds the images on its command line as u_tex0, u_tex1, ..;
// marchstudio takes them with --texture. Throws bad_input for the first
// input that is an image file (by its extension), before any job runs.
void refuse_image_inputs(const std::vector<std::string>& inputs);

}  // namespace ms
