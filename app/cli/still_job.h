// The still pipeline: a RenderJob (cli/render_job.h) in, one image file out,
// drawn in a GL context and with programs that a RenderSession keeps from
// job to job. A batch (cli/batch.h) renders all its jobs in one session, so
// the context is made once and a program whose assembled text another job
// already compiled is reused (render/program_cache.h); the files are the
// same, bit for bit, as one process per image writes.
//
//   RenderSession session;                 // the context comes with the first job
//   render_still_job(job, session);        // throws ms::Error; no file on failure
//   session.cache.misses();                // programs compiled so far
#pragma once
#include <filesystem>
#include <memory>
#include <vector>

#include "cli/bounds_report.h"
#include "cli/render_job.h"
#include "gl/context.h"
#include "render/program_cache.h"

namespace ms {

struct RenderSession {
  std::unique_ptr<Context> context;  // made by the first job that needs it, with its backend
  Backend backend = Backend::automatic;
  // Declared after the context: its programs die first, while it is current.
  ProgramCache cache{64};
  BoundsReport bounds;  // the [bounds] warning, once per scene of the batch
};

// Loads, assembles, draws and writes job.output (atomically, verified);
// the caller prints the path. Everything that can fail on bad input fails
// before the context is made. With job.verbose: the backend, the phases'
// times and how many programs were compiled or taken from the cache.
void render_still_job(const RenderJob& job, RenderSession& session);

// Removes the temporaries of `outputs` left by killed runs (io/temp_cleanup.h),
// one line each on stderr; once per run, before the first job.
void say_removed_temps(const std::vector<std::filesystem::path>& outputs);

// --print-shader: the job's assembled passes on stdout; nothing is drawn.
void print_job_shader(const RenderJob& job);

}  // namespace ms
