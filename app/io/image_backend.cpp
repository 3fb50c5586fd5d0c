#include "io/image_backend.h"

#include <dlfcn.h>

#include <future>
#include <mutex>

#include "core/error.h"
#include "io/module_file.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

struct Loaded {
  const ImageBackend* backend = nullptr;
  std::string error;  // why not, when backend is null
};

Loaded load(const fs::path& path) {
  Loaded l;
  void* lib = open_module(path, l.error);
  if (!lib) return l;
  using Entry = const ImageBackend* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(lib, kImageBackendSymbol));
  if (!entry) l.error = std::string("no ") + kImageBackendSymbol + " in it";
  else l.backend = entry();
  return l;  // never dlclose'd: it lives as long as the process
}

// std::async's future: its last copy waits for the load in its destructor,
// so exit() never runs the dynamic loader's teardown under a dlopen.
std::mutex g_mutex;
std::shared_future<Loaded> g_loaded;

}  // namespace

fs::path image_backend_path() {
  return module_path("MARCH_IMAGE_MODULE", kImageBackendFile, MARCH_IMAGE_MODULE_DIR);
}

void preload_image_backend() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!g_loaded.valid()) g_loaded = std::async(std::launch::async, [] { return load(image_backend_path()); }).share();
}

const ImageBackend& image_backend() {
  preload_image_backend();
  std::shared_future<Loaded> loaded;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    loaded = g_loaded;
  }
  const Loaded& l = loaded.get();
  if (!l.backend)
    throw Error({Exit::system, image_backend_path().string(), 0, {},
                 "cannot load the image I/O module (OpenImageIO): " + l.error,
                 "keep it beside the marchstudio executable or in ../lib/marchstudio/ from it, or set "
                 "MARCH_IMAGE_MODULE to its path", {}});
  return *l.backend;
}

}  // namespace ms
