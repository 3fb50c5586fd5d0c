#include "io/image_backend.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <future>
#include <mutex>

#include "core/error.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

struct Loaded {
  const ImageBackend* backend = nullptr;
  std::string error;  // why not, when backend is null
};

Loaded load(const fs::path& path) {
  Loaded l;
  // RTLD_LOCAL: OpenImageIO's dependencies never resolve our symbols or the GL's.
  void* lib = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* e = dlerror();
    l.error = e ? e : "dlopen failed";
    return l;
  }
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

// A build tree, or a copy made by hand, keeps the module beside the
// executable; `cmake --install` puts it in lib/marchstudio/, beside bin/.
fs::path image_backend_path() {
  if (const char* env = std::getenv("MARCH_IMAGE_MODULE"); env && *env) return env;
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    const fs::path dir = fs::path(std::string(exe, static_cast<size_t>(n))).parent_path();
    for (const fs::path& p : {dir / kImageBackendFile, dir / "../lib/marchstudio" / kImageBackendFile}) {
      std::error_code ec;
      if (fs::exists(p, ec)) return p.lexically_normal();
    }
  }
  return fs::path(MARCH_IMAGE_MODULE_DIR) / kImageBackendFile;
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
