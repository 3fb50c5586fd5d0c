// The scene pass as a compute shader: the assembled fragment
// source of a scene (shader/assemble.h), rewritten so the same text runs as
// a GL 4.3+ compute shader, one invocation per pixel. No GL here.
//
//   - `layout(location = N) out vec4 NAME;` becomes a plain global
//     `vec4 NAME`, and the wrapper's main() stores it into image unit N
//     (rgba32f), adding what the image holds when uMsAccumulate is 1: the
//     fragment path's additive blending, sample by sample, in the same order;
//   - gl_FragCoord becomes msComputeCoord = (pixel + 0.5, 0, 1), the pixel
//     being uMsRect.xy (the tile's lower-left corner) + gl_GlobalInvocationID.xy;
//   - texture(s, P) becomes textureLod(s, P, 0.0) (and textureOffset,
//     textureProj, textureProjOffset their Lod forms): no derivatives, so no
//     implicit LOD; the same texel on a texture without mip maps;
//   - the fragment's main() is renamed msSceneMain() and called as it is.
// Locations 1..3 (the AOV targets) are stored only under AOV_OUTPUTS, as
// main.frag declares them. The work group is MS_GROUP_X x MS_GROUP_Y, in
// the order MS_STRIPE gives (ComputeGroup).
#pragma once
#include <optional>
#include <string>

#include "preprocess/preprocess.h"

namespace ms {

struct ComputeGroup {
  int x = 8, y = 8;  // invocations per work group; x * y <= 1024
  // 0: a tile's groups dispatched as a grid (row order). N > 0: as one row
  // of groups, remapped in the shader to stripes of N group rows walked
  // column by column (MS_STRIPE), so groups that run at once are close.
  int stripe = 0;
};

// "8x8", "16x8/4" (a stripe order): --compute-group's form.
std::string group_name(const ComputeGroup& g);
// group_name()'s inverse: "WxH" (each >= 1, W x H <= 1024) or "WxH/N"
// (stripe 0..1024); none for anything else.
std::optional<ComputeGroup> parse_group_name(const std::string& text);

// The first derivative function (dFdx, dFdy, fwidth and their Fine/Coarse
// forms) the text calls outside comments, or "" when there is none: a
// compute shader has no pixel quads to take them from.
std::string first_derivative_call(const std::string& glsl);

// `frag` rewritten as above. Throws bad_input (key "--dispatch", at the
// call's file:line) when the text calls a derivative function, or calls an
// implicit-LOD lookup (texture, textureOffset, textureProj,
// textureProjOffset) while `mipmapped_inputs`; or has no single `void main(`.
ShaderSource wrap_compute(const ShaderSource& frag, ComputeGroup group = {}, bool mipmapped_inputs = false);

}  // namespace ms
