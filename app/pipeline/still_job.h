// The still pipeline: a FrameJob (pipeline/frame_job.h) in, one image file out,
// drawn in a GL context and with programs that a FrameSession keeps from
// job to job. A batch (cli/batch.h) renders all its jobs in one session, so
// the context is made once and a program whose assembled text another job
// already compiled is reused (render/program_cache.h); the files are the
// same, bit for bit, as one process per image writes.
//
//   FrameSession session;             // the context comes with the first job
//   render_still_job(job, session);   // throws ms::Error; no file on failure
//   session.cache().misses();         // programs compiled so far
#pragma once
#include <filesystem>
#include <vector>

#include "pipeline/frame_job.h"
#include "pipeline/frame_session.h"

namespace ms {

// Loads, assembles, draws and writes job.output (atomically, verified);
// the caller prints the path. Everything that can fail on bad input fails
// before the context is made. With job.verbose: the backend, the phases'
// times and how many programs were compiled or taken from the cache.
void render_still_job(const FrameJob& job, FrameSession& session);

// Removes the temporaries of `outputs` left by killed runs (io/temp_cleanup.h),
// one line each on stderr; once per run, before the first job.
void say_removed_temps(const std::vector<std::filesystem::path>& outputs);

// --print-shader: the job's assembled passes on stdout; nothing is drawn.
void print_job_shader(const FrameJob& job);

}  // namespace ms
