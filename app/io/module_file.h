// Finding and opening marchstudio's dlopen'd modules: marchstudio-oiio.so
// (io/image_backend.h) and marchstudio-vdb.so (mesh/vdb_module.h). Each
// keeps a heavy library and its dependencies out of the executable, so
// that --version and --help load none of them (docs/performance.md#start-up).
//
//   const auto path = module_path("MARCH_VDB_MODULE", "marchstudio-vdb.so", build_dir);
//   std::string why;
//   void* lib = open_module(path, why);   // null, and `why` says why not
//   auto* f = dlsym(lib, "...");          // never dlclose'd
#pragma once
#include <filesystem>
#include <string>

namespace ms {

// Where a module is looked for, in order: $`env` (when set and not empty),
// beside the executable, ../lib/marchstudio/ from it (an installed tree),
// then `build_dir` (the build tree the binary was built in).
std::filesystem::path module_path(const char* env, const char* file, const std::filesystem::path& build_dir);

// dlopen(RTLD_NOW | RTLD_LOCAL) after checking that `path` is a regular file
// holding a whole shared object: a cut-short copy would be SIGBUS inside
// dlopen, a FIFO would block it. Null with `error` set when it cannot be.
void* open_module(const std::filesystem::path& path, std::string& error);

}  // namespace ms
