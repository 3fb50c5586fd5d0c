#include "cli/render_cmd.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "cli/shader_dir.h"
#include "core/error.h"
#include "gl/context.h"
#include "io/image_io.h"
#include "render/frame.h"
#include "render/uniforms.h"
#include "cli/input.h"

namespace ms {
namespace fs = std::filesystem;

CLI::App* add_render_command(CLI::App& app, RenderArgs& a) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene (.toml) or a Shadertoy shader (.glsl) to an image");
  cmd->add_option("input", a.input, "Scene .toml or Shadertoy .glsl/.frag")->required();
  cmd->add_option("-o,--output", a.output, "Output image: .png .jpg .tif (8-bit sRGB) or .exr (linear float)");
  cmd->add_option("--size", a.size, "Image size WxH (default: the scene's)");
  cmd->add_option("--time", a.time, "Scene time in seconds (default 0)")->each([&a](const std::string&) {
    a.time_set = true;
  });
  cmd->add_option("--spp", a.spp, "Samples per pixel, stratified (default: the scene's)");
  cmd->add_option("--frame", a.frame, "Frame number (uFrame / iFrame)");
  cmd->add_option("--backend", a.backend, "GL context: auto, egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  cmd->add_option("--shader-dir", a.shader_dir, "The sdf_shaders/ directory");
  cmd->add_option("--disable", a.disable, "Switch effects off: shadows, reflections, ao, checker-filter")
      ->delimiter(',')
      ->check(CLI::IsMember({"shadows", "reflections", "ao", "checker-filter"}));
  cmd->add_option("-D,--define", a.defines, "Inject #define NAME VALUE into the scene shader (NAME or NAME=VALUE)");
  cmd->add_flag("-v,--verbose", a.verbose, "Print the backend, GL renderer and timings");
  return cmd;
}

namespace {

struct Size {
  int width = 0, height = 0;
};

Size parse_size(const std::string& s) {
  static const std::regex re(R"(^\s*(\d{1,9})\s*[xX]\s*(\d{1,9})\s*$)");
  std::smatch m;
  if (!std::regex_match(s, m, re))
    fail_input("invalid size '" + s + "'", {}, 0, "--size", "expected WxH, e.g. 1280x720");
  Size out{std::stoi(m[1]), std::stoi(m[2])};
  if (out.width < 1 || out.height < 1)
    fail_input("image size " + s + " must be at least 1x1", {}, 0, "--size");
  return out;
}

// Seconds since the last lap, for --verbose phase timings.
struct Stopwatch {
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  }
};

// iChannel0..3 read black, as an unbound Shadertoy input does.
struct BlackChannels {
  GLuint tex = 0;
  BlackChannels() {
    const float black[4] = {0, 0, 0, 1};
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, black);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  void bind() const {
    for (int i = 0; i < 4; ++i) {
      glActiveTexture(GL_TEXTURE0 + i);
      glBindTexture(GL_TEXTURE_2D, tex);
    }
    glActiveTexture(GL_TEXTURE0);
  }
  ~BlackChannels() { glDeleteTextures(1, &tex); }
};

}  // namespace

int run_render(const RenderArgs& a) {
  if (!std::isfinite(a.time)) fail_input("--time must be a finite number", {}, 0, "--time");
  if (a.spp < 0 || a.spp > 1024) fail_input("--spp must be in 1..1024", {}, 0, "--spp");
  if (a.frame < 0) fail_input("--frame must be >= 0", {}, 0, "--frame");
  const Backend backend = parse_backend(a.backend);
  const fs::path input = a.input;
  const fs::path output = a.output.empty() ? fs::path(input.stem().string() + ".png") : fs::path(a.output);
  check_output_path(output);  // before any work: no file is ever half-made
  const bool display = is_display_format(image_format_for(output));

  const AssembleOptions opts{resolve_shader_dir(a.shader_dir), parse_defines(a.defines)};
  const LoadedInput in = load_input(input, a.disable, opts);
  const Scene& scene = in.scene;
  FrameParams fp;
  fp.width = scene.render.width;
  fp.height = scene.render.height;
  if (!a.size.empty()) {
    const Size s = parse_size(a.size);
    fp.width = s.width;
    fp.height = s.height;
  }
  fp.spp = a.spp > 0 ? a.spp : scene.render.spp;
  fp.exposure = scene.render.exposure;
  const float time = a.time_set ? static_cast<float>(a.time) : scene.render.time;
  // Shadertoy output is display-referred already: never encoded again.
  const ShaderSource post_src = assemble_post(scene.render.tonemap, display && !in.shadertoy, opts);

  Stopwatch clock;
  std::unique_ptr<Context> ctx = create_headless_context(backend);
  const double t_context = clock.lap();
  if (a.verbose)
    std::fprintf(stderr, "marchstudio: backend %s, GL_RENDERER %s, GL_VERSION %s\n", ctx->backend().c_str(),
                 ctx->info().renderer.c_str(), ctx->info().version.c_str());
  check_frame_size(ctx->info(), fp.width, fp.height);

  const Program main_prog(fullscreen_vertex_source(), in.main);
  const Program post_prog(fullscreen_vertex_source(), post_src);
  const double t_compile = clock.lap();
  FrameRenderer renderer(*ctx);
  Image img;
  if (!in.shadertoy) {
    img = renderer.render(main_prog, [&](const Program& p) {
      set_scene_uniforms(p, scene, fp.width, fp.height, time, a.frame);
    }, post_prog, fp);
  } else {
    BlackChannels channels;
    ShadertoyInputs st;
    st.time = time;
    st.frame = a.frame;
    img = renderer.render(main_prog, [&](const Program& p) {
      channels.bind();
      set_shadertoy_uniforms(p, fp.width, fp.height, st);
    }, post_prog, fp);
  }
  ImageMetadata meta{{"Software", "marchstudio 0.1.0"},
                     {"ImageDescription", input.filename().string() + " t=" + std::to_string(time) +
                                              " spp=" + std::to_string(fp.spp)}};
  const double t_render = clock.lap();
  write_image(img, output, meta);
  if (a.verbose)
    std::fprintf(stderr, "marchstudio: context %.1f ms, compile %.1f ms, render %.1f ms, write %.1f ms\n",
                 t_context * 1e3, t_compile * 1e3, t_render * 1e3, clock.lap() * 1e3);
  std::printf("%s\n", output.string().c_str());
  return 0;
}

}  // namespace ms
