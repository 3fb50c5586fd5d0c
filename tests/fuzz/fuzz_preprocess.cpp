// The #include / #pragma once preprocessor and the driver-log mapping, over
// a small file tree. The input is split at lines "//---": the first part is
// the root shader, the next ones become scene/a.glsl, scene/b.glsl,
// scene/sub/c.glsl and lib/d.glsl (found through include_dirs, like
// sdf_shaders/); files without a part do not exist. Includes are confined
// to scene/ and lib/; scene/escape.glsl and scene/up/ are symlinks leading
// out. Properties: only ms::Error escapes; no output, dependency or error
// message ever holds the canary or a file outside the roots; the root part,
// read as a driver info log, maps without crashing; the viewer's parameter
// scan (live/param_reload.h) reads the result without crashing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "fuzz_util.h"
#include "live/param_reload.h"
#include "preprocess/log_map.h"
#include "preprocess/preprocess.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ms;
  namespace fs = std::filesystem;
  fuzz::Workspace& ws = fuzz::workspace();
  const std::array<fs::path, 4> files = {ws.scene() / "a.glsl", ws.scene() / "b.glsl", ws.scene() / "sub/c.glsl",
                                         ws.lib() / "d.glsl"};
  std::vector<std::string_view> parts;
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  // The canary must come from the secret file, not from the input itself.
  if (fuzz::leaks_canary(rest)) return 0;
  constexpr std::string_view kSep = "\n//---\n";
  for (;;) {
    const size_t at = rest.find(kSep);
    parts.push_back(rest.substr(0, at));
    if (at == std::string_view::npos) break;
    rest = rest.substr(at + kSep.size());
  }
  for (size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    if (i + 1 < parts.size()) fuzz::put(files[i], parts[i + 1]);
    else fs::remove(files[i], ec);
  }
  PreprocessOptions opts;
  opts.include_dirs = {ws.lib()};
  opts.roots = {ws.scene(), ws.lib()};
  // The budgets scaled down (the release ones: 2^20 tokens, 8 MiB, depth
  // 50 000), so that a macro bomb or a macro-made deep expression reaches
  // its limit within the fuzzer's 10 s per input in the instrumented
  // ASan + UBSan build (the full token budget takes about 30 s there, under
  // 0.1 s in the release replay).
  // The same code paths; the release values are tests/cli/test_attacks_*'s.
  opts.limits.max_expanded_tokens = std::size_t{1} << 14;
  opts.limits.max_text_bytes = std::size_t{256} << 10;
  opts.limits.max_expression_depth = 2000;
  ShaderSource src;
  try {
    src = preprocess(parts[0], "root.frag", ws.scene(), opts);
  } catch (const Error& e) {
    if (fuzz::leaks_canary(e.what())) fuzz::violated("preprocess error shows the canary", e.what());
    return 0;
  }
  if (fuzz::leaks_canary(src.text)) fuzz::violated("preprocessed text holds the canary", src.text);
  for (const fs::path& dep : src.dependencies)
    if (!within_roots(dep, opts.roots)) fuzz::violated("a dependency outside the roots was read", dep.string());
  live::parse_scene_params(src.text);
  const std::string mapped = format_diagnostics(parse_info_log(parts[0], src));
  if (fuzz::leaks_canary(mapped)) fuzz::violated("mapped log shows the canary", mapped);
  return 0;
}
