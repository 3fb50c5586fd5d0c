// `render`'s flags (or one line of a --jobs file, cli/job_list.h) as the
// FrameJob the still pipeline reads (pipeline/frame_job.h): each value
// checked and every error naming its flag.
//
//   FrameJob job = make_render_job(args, args.inputs[0]);  // throws ms::Error
//   render_still_job(job, session);                         // pipeline/still_job.h
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/frame_job.h"

namespace ms {

struct RenderArgs;

// The job for `input` under args' flags (args.input and args.inputs are
// not read; args.output is, unless `output` is given). Throws bad_input
// naming the flag of the first bad value; the output path is checked as
// check_output_path() does, so a job that passes leaves no file half-made.
FrameJob make_render_job(const RenderArgs& args, const std::filesystem::path& input,
                         const std::filesystem::path& output = {});

}  // namespace ms
