// marchstudio._marchstudio: the Python package's native half (docs/python.md).
// A thin layer over pipeline/: a scene file in, the same jobs the command
// line runs, their pixels and meshes handed to numpy without a copy. The
// package's Python half (python/marchstudio/) passes every path explicitly:
// the shader directory here, the image and VDB modules through their
// documented variables (io/module_file.h), so nothing is looked up twice.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>

#include <atomic>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

#include "bench/bench.h"
#include "bench/bench_plan.h"
#include "bench/bench_report.h"
#include "core/error.h"
#include "job_thread.h"
#include "io/image_io.h"
#include "pipeline/input.h"
#include "pipeline/mesh_job.h"
#include "pipeline/shader_dir.h"
#include "pipeline/still_job.h"
#include "render/aov.h"
#include "scene/animation.h"
#include "shader/assemble.h"
#include "shader/specialize.h"

namespace nb = nanobind;
namespace fs = std::filesystem;
using marchstudio_py::gl_thread;
using marchstudio_py::g_interrupted;
using marchstudio_py::Interrupted;
using marchstudio_py::InterruptScope;

namespace {

// One GL context for the interpreter, made by the first render or mesh and
// never torn down: a driver unloaded during the interpreter's exit may crash.
// A context is current on one thread, the one that made it, so every job
// runs on one thread of the extension's; Python threads queue for it.
ms::FrameSession* g_session = nullptr;

fs::path g_shader_dir;

ms::FrameSession& session() {
  if (!g_session) g_session = new ms::FrameSession;
  return *g_session;
}

const fs::path& shader_dir() {
  if (g_shader_dir.empty()) throw ms::Error({ms::Exit::system, {}, 0, {}, "marchstudio: no shader directory set", {}, {}});
  return g_shader_dir;
}

ms::Backend backend_of(const std::string& name) { return ms::parse_backend(name); }

ms::FrameJob frame_job(const std::string& input, const std::string& backend, const std::string& preset,
                       std::optional<float> time) {
  ms::FrameJob job;
  job.input = input;
  job.label = input;
  job.backend = backend_of(backend);
  job.shader_dir = shader_dir();
  job.preset = preset;
  job.time = time;
  return job;
}

// A scratch folder beside nothing else: a notebook's PNG is the file the
// render's own atomic write lands there, read back as bytes.
struct ScratchDir {
  fs::path dir;
  ScratchDir() {
    static std::atomic<int> n{0};
    dir = fs::temp_directory_path() / ("marchstudio-py-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
    fs::create_directories(dir);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

template <class T>
nb::capsule owner_of(std::vector<T>* v) {
  return nb::capsule(v, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
}

// The image as (H, W, 4): float32 linear (the EXR a render writes) or
// uint8 display values (the PNG), alpha 1 where the file has none.
nb::object render(const std::string& input, int width, int height, std::optional<float> time, int spp,
                  const std::string& preset, const std::string& backend, bool uint8) {
  ms::FrameJob job = frame_job(input, backend, preset, time);
  job.size = {width, height};
  job.spp = spp;
  // Handed back in memory, as the PNG or EXR `marchstudio render` writes
  // would hold it (pipeline/frame_job.h): nothing is written.
  job.output = uint8 ? "frame.png" : "frame.exr";
  ms::Image img;
  job.image_out = &img;
  {
    InterruptScope interrupt;
    {
      nb::gil_scoped_release release;
      gl_thread().run([&] { ms::render_still_job(job, session()); });
    }
    InterruptScope::raise_if_interrupted(false);
  }
  const std::size_t w = img.width, h = img.height, nc = img.channels.size(), n = w * h;
  const size_t shape[3] = {h, w, 4};
  if (uint8) {
    auto* out = new std::vector<std::uint8_t>(n * 4, 255);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < std::min<std::size_t>(nc, 4); ++c)
        (*out)[i * 4 + c] = static_cast<std::uint8_t>(img.pixels[i * nc + c] * 255.0f + 0.5f);
    return nb::cast(nb::ndarray<nb::numpy, std::uint8_t, nb::ndim<3>>(out->data(), 3, shape, owner_of(out)));
  }
  auto* out = new std::vector<float>;
  if (nc == 4) {
    *out = std::move(img.pixels);  // no copy: the array owns the render's buffer
  } else {
    out->assign(n * 4, 1.0f);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < std::min<std::size_t>(nc, 4); ++c) (*out)[i * 4 + c] = img.pixels[i * nc + c];
  }
  return nb::cast(nb::ndarray<nb::numpy, float, nb::ndim<3>>(out->data(), 3, shape, owner_of(out)));
}

using Box = std::optional<std::tuple<float, float, float, float, float, float>>;

// The mesh job of `marchstudio mesh`: to `output` when given, else to
// arrays. Returns (report JSON, vertices (N, 3) float32 or None, faces
// (M, 3) uint32 or None).
nb::tuple mesh(const std::string& input, const std::string& output, int resolution, double voxel, Box bounds,
               std::optional<float> time, const std::string& backend, bool arrays, int band) {
  ms::MeshJob job;
  job.frame = frame_job(input, backend, {}, time);
  job.output = output;
  job.resolution = resolution;
  job.voxel = voxel;
  job.band = band;
  if (bounds) {
    auto [x0, y0, z0, x1, y1, z1] = *bounds;
    job.bounds = ms::MeshBox{{x0, y0, z0}, {x1, y1, z1}};
  }
  ms::TriMesh tri;
  if (arrays) job.mesh_out = &tri;
  ms::MeshReport r;
  {
    InterruptScope interrupt;
    bool cut_short = false;
    try {
      nb::gil_scoped_release release;
      gl_thread().run([&] {
        r = ms::mesh_scene(job, session(), [](const char*, double) {
          if (g_interrupted) throw Interrupted{};
        });
      });
    } catch (const Interrupted&) {
      cut_short = true;
    }
    InterruptScope::raise_if_interrupted(cut_short);
  }
  const std::string report = ms::mesh_report_json(r);
  if (!arrays) return nb::make_tuple(report, nb::none(), nb::none());
  auto* v = new std::vector<float>(tri.positions.size() * 3);
  for (std::size_t i = 0; i < tri.positions.size(); ++i)
    for (int c = 0; c < 3; ++c) (*v)[i * 3 + c] = tri.positions[i][c];
  auto* f = new std::vector<std::uint32_t>(std::move(tri.indices));
  const size_t vs[2] = {tri.positions.size(), 3}, fs_[2] = {f->size() / 3, 3};
  return nb::make_tuple(report, nb::ndarray<nb::numpy, float, nb::ndim<2>>(v->data(), 2, vs, owner_of(v)),
                        nb::ndarray<nb::numpy, std::uint32_t, nb::ndim<2>>(f->data(), 2, fs_, owner_of(f)));
}

// The box a mesh covers by default: the scene's [bounds] (a graph's own).
std::optional<std::tuple<float, float, float, float, float, float>> scene_box(const std::string& input) {
  ms::AssembleOptions opts;
  const ms::LoadedInput in = ms::load_input_scene(input, {}, opts);
  const ms::Bounds& b = in.scene.bounds;
  if (b.kind == ms::BoundsKind::box) return std::make_tuple(b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
  if (b.kind == ms::BoundsKind::sphere) {
    const glm::vec3 lo = b.center - b.radius, hi = b.center + b.radius;
    return std::make_tuple(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  }
  return std::nullopt;
}

// A render's PNG file, bytes as written: a notebook's picture of a scene.
nb::bytes render_png(const std::string& input, int width, int height, const std::string& backend) {
  ms::FrameJob job = frame_job(input, backend, {}, std::nullopt);
  job.size = {width, height};
  ScratchDir scratch;
  job.output = scratch.dir / "frame.png";
  std::string data;
  {
    InterruptScope interrupt;
    {
      nb::gil_scoped_release release;
      gl_thread().run([&] { ms::render_still_job(job, session()); });
      std::ifstream in(job.output, std::ios::binary);
      data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    InterruptScope::raise_if_interrupted(false);
  }
  return nb::bytes(data.data(), data.size());
}

// `marchstudio bench --json`'s document for a scene, on the GL thread:
// the bench `marchstudio bench` plans (bench/bench_plan.h), without the
// flags' extras (overrides, --dispatch, --strict, the bounds warning).
std::string bench_on_gl_thread(const ms::FrameJob& job, int width, int height, int frames, int warmup) {
  const ms::BenchPlan b = ms::plan_bench(job, {width, height}, frames, warmup);
  ms::check_bench_settings(b.s);
  ms::FrameSession& fs = session();
  fs.context(job.backend);
  const ms::BenchResult r = ms::run_planned_bench(fs, b);
  const ms::BenchSubject subject{job.input.string(), b.p.in.scene.name, {},
                                 ms::specialization_name(b.p.opts.specialize), {}};
  return ms::bench_json(subject, b.s, r);
}

// `marchstudio bench --json`'s document for a scene, timed in this
// process's context (the one renders use, so the driver's shader cache is
// as the process found it, not switched off as the command line does).
std::string bench(const std::string& input, int width, int height, int frames, int warmup, int spp,
                  const std::string& backend) {
  ms::FrameJob job = frame_job(input, backend, {}, std::nullopt);
  job.spp = spp;
  std::string text;
  nb::gil_scoped_release release;
  gl_thread().run([&] { text = bench_on_gl_thread(job, width, height, frames, warmup); });
  return text;
}

// An image file as (H, W, C) float32, read as `compare` reads it.
nb::object read_image(const std::string& path) {
  ms::Image img;
  {
    nb::gil_scoped_release release;
    img = ms::read_image(path);
  }
  auto* out = new std::vector<float>(std::move(img.pixels));
  const size_t shape[3] = {static_cast<size_t>(img.height), static_cast<size_t>(img.width), img.channels.size()};
  return nb::cast(nb::ndarray<nb::numpy, float, nb::ndim<3>>(out->data(), 3, shape, owner_of(out)));
}

}  // namespace

NB_MODULE(_marchstudio, m) {
  m.doc() = "marchstudio's native half: renders and meshes through the C++ pipeline";
  static nb::exception<ms::Error> error(m, "Error", PyExc_RuntimeError);
  // The one line the command line prints after "marchstudio: ".
  nb::register_exception_translator([](const std::exception_ptr& p, void*) {
    try {
      std::rethrow_exception(p);
    } catch (const ms::Error& e) {
      PyErr_SetString(error.ptr(), ms::format_error(e.info()).c_str());
    }
  });
  m.def("set_shader_dir", [](const std::string& dir) { g_shader_dir = ms::resolve_shader_dir(dir); }, nb::arg("dir"),
        "Sets the sdf_shaders/ directory every job uses (it must hold main.frag).");
  m.def("render", &render, nb::arg("input"), nb::arg("width") = 0, nb::arg("height") = 0, nb::arg("time") = nb::none(),
        nb::arg("spp") = 0, nb::arg("preset") = "", nb::arg("backend") = "auto", nb::arg("uint8") = false,
        "Renders a scene file as `marchstudio render` does; an (H, W, 4) array.");
  m.def("mesh", &mesh, nb::arg("input"), nb::arg("output") = "", nb::arg("resolution") = 256, nb::arg("voxel") = 0.0,
        nb::arg("bounds") = nb::none(), nb::arg("time") = nb::none(), nb::arg("backend") = "auto",
        nb::arg("arrays") = true, nb::arg("band") = 3, "Meshes a scene file as `marchstudio mesh` does.");
  m.def("render_png", &render_png, nb::arg("input"), nb::arg("width"), nb::arg("height"), nb::arg("backend") = "auto",
        "A render's PNG file as bytes.");
  m.def("bench", &bench, nb::arg("input"), nb::arg("width") = 0, nb::arg("height") = 0, nb::arg("frames") = 30,
        nb::arg("warmup") = 3, nb::arg("spp") = 0, nb::arg("backend") = "auto",
        "`marchstudio bench --json`'s document (schema marchstudio.bench/1) as a string.");
  m.def("read_image", &read_image, nb::arg("path"), "An image file as an (H, W, C) float32 array.");
  m.def("scene_box", &scene_box, nb::arg("input"), "The scene's own box (x0, y0, z0, x1, y1, z1), or None.");
}
