#include "pipeline/bloom_setup.h"

#include "shader/assemble.h"

namespace ms {

bool bloom_on(const LoadedInput& in, bool display) {
  const Bloom& b = in.scene.bloom;
  return b.enabled && !in.shadertoy && (display || b.exr);
}

std::unique_ptr<BloomStage> make_bloom_stage(const LoadedInput& in, bool display, const AssembleOptions& opts,
                                             ProgramCache& cache) {
  if (!bloom_on(in, display)) return nullptr;
  const std::string vs = fullscreen_vertex_source();
  return std::make_unique<BloomStage>(in.scene.bloom, cache.get(vs, assemble_bloom(false, opts)),
                                      cache.get(vs, assemble_bloom(true, opts)));
}

}  // namespace ms
