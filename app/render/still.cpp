#include "render/still.h"

#include "core/error.h"
#include "render/uniforms.h"

namespace ms {

void draw_still(FrameRenderer& renderer, const Program& main, const Program& post, const StillFrame& f) {
  if (!f.scene) fail_system("internal: a still without a scene");
  const FrameParams& fp = f.params;
  if (f.scene->shadertoy_file.empty()) {
    renderer.draw(main, [&](const Program& p) {
      set_scene_uniforms(p, *f.scene, fp.width, fp.height, f.time, f.frame);
    }, post, fp);
  } else {
    BlackChannels channels;
    ShadertoyInputs st;
    st.time = f.time;
    st.time_delta = f.time_delta;
    st.frame = f.frame;
    renderer.draw(main, [&](const Program& p) {
      channels.bind();
      set_shadertoy_uniforms(p, fp.width, fp.height, st);
    }, post, fp);
  }
}

Still render_still(FrameRenderer& renderer, const Program& main, const Program& post, const StillFrame& f) {
  draw_still(renderer, main, post, f);
  Still out;
  out.color = renderer.read_color();
  if (f.params.aovs) out.aovs = renderer.read_aovs();
  return out;
}

}  // namespace ms
