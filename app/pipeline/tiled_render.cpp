#include "pipeline/tiled_render.h"

#include <unistd.h>

#include <chrono>

#include "core/clock.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_stream.h"
#include "io/temp_cleanup.h"
#include "pipeline/progress.h"
#include "render/aov.h"
#include "render/tiled_still.h"

namespace ms {
namespace fs = std::filesystem;

StillTiling plan_render_tiling(const LoadedInput& in, const FrameParams& fp, int gpu_targets, int forced, int max_w,
                               int max_h) {
  if (!in.stateful()) {
    const int targets = gpu_targets + (in.scene.bloom.enabled ? 2 : 0);  // render/bloom.h's two, at most full size
    StillTiling t = plan_still_tiling(fp.width, fp.height, max_w, max_h, targets, fp.aovs, forced);
    if (t.tiled() && in.scene.bloom.enabled)  // docs/post.md: a tile's blur would miss its neighbours' light
      fail_input("bloom needs the whole frame, so a still drawn in tiles cannot have it", in.path.string(), 0,
                 forced > 0 ? "--tile-still" : "--size", "--disable bloom, or render it smaller");
    return t;
  }
  const std::string size = std::to_string(fp.width) + "x" + std::to_string(fp.height);
  const std::string why = "a shader with buffers needs them whole-frame, so it cannot be drawn in tiles";
  if (forced > 0) fail_input(why, {}, 0, "--tile-still");
  if (fp.width > max_w || fp.height > max_h)
    fail_input("image size " + size + " exceeds this GL's limit of " + std::to_string(max_w) + "x" +
                   std::to_string(max_h) + ", and " + why,
               {}, 0, "--size", "render it smaller");
  check_frame_memory(frame_memory(fp.width, fp.height, gpu_targets, fp.aovs), fp.width, fp.height, why);
  return {};
}

void render_tiled_file(const TiledFile& job, FrameSession& session, const StillFrame& still,
                       const StillTiling& tiling) {
  const FrameParams& fp = still.params;
  std::vector<std::string> channels = {"R", "G", "B", "A"};
  channels.insert(channels.end(), job.aov_names.begin(), job.aov_names.end());
  // The signal handler and the watchdog's hook go in before the writer
  // makes its temporary (the name is AtomicFile's, io/atomic_file.h): a
  // signal or the deadline between the two, while the codec is set up, used
  // to leave the temporary behind.
  // While a tiled still streams (minutes, gigabytes), Ctrl-C and SIGTERM
  // (scancel, a farm's time limit) remove the temporary and end the process
  // with 130 / 143 (io/temp_cleanup.h, as every still); SIGKILL cannot be
  // caught and leaves only the temporary, never the target.
  const fs::path temp = temp_path_for(job.output, ::getpid());
  const RemoveTempOnSignal on_signal(job.output);
  if (job.watchdog && job.deadline && job.deadline->limited())
    job.watchdog->arm(*job.deadline, "the render", [temp] { ::unlink(temp.c_str()); });
  ImageStreamWriter out(job.output, fp.width, fp.height, channels, job.meta);

  Progress progress(static_cast<int>(still_tiles(fp.width, fp.height, tiling).size()), ::isatty(2) == 1, stderr,
                    "tiles");
  progress.start();
  struct EndBar {  // an error's line then starts on a line of its own
    Progress& p;
    ~EndBar() { p.finish(); }
  } end_bar{progress};
  Stopwatch tile;
  long long nonfinite = 0;
  render_still_tiled(
      [&](const StillFrame& piece) { return session.draw(piece); }, session.graph(), still, tiling,
      [&](StillBand& band) {
        Still& s = band.pixels;
        nonfinite += count_nonfinite_pixels(s.color, fp.aovs ? &s.aovs : nullptr) + s.flagged;
        if (fp.aovs) s.color = append_channels(s.color, select_channels(s.aovs, job.aov_names));
        out.write_rows(band.top, s.color);
      },
      [&](int done, int) {
        progress.rendered(done, tile.lap());
      });
  progress.finish();
  if (job.watchdog) job.watchdog->disarm();  // the rename must not be cut short
  guard_nonfinite(job.nonfinite, nonfinite, static_cast<long long>(fp.width) * fp.height);
  out.finish();
}

}  // namespace ms
