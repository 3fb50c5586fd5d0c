// The Shadertoy JSON loader (importers/project_json.h) on any text: the API's
// and the export's forms, then check_project() and, for every pass, the
// desktop-keyword renaming. Only ms::Error may escape; the renaming keeps
// every line where it was (error lines map back) and is idempotent (a
// renamed name is never a keyword again).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fuzz_util.h"
#include "importers/es_compat.h"
#include "scene/project.h"
#include "importers/project_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ms;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    ShaderProject p = load_shadertoy_json(text, "fuzz.json");
    check_project(p, "fuzz.json");
    for (const ProjectPass& pass : p.passes) {
      const std::string once = rename_desktop_keywords(pass.code);
      if (std::count(once.begin(), once.end(), '\n') != std::count(pass.code.begin(), pass.code.end(), '\n'))
        fuzz::violated("renaming moved a line", pass.code);
      if (rename_desktop_keywords(once) != once) fuzz::violated("renaming is not idempotent", pass.code);
    }
  } catch (const Error&) {
  }
  return 0;
}
