// `render A.toml B.toml ... --output-dir DIR` and `render --jobs FILE`: many
// stills in one process, one GL context and one program cache
// (pipeline/still_job.h), each written as the same file one `render` per image
// would write (docs/usage.md#batches).
//
// Positional inputs go to DIR/<stem>.<format> (DIR: the current directory
// when not given; format: --format, default png). Two inputs that would
// write the same file (one stem) are refused before anything is rendered.
// The job file is streamed (cli/job_list.h): each line renders as it is
// read, and one whose output an earlier job writes fails alone, as every
// other failure is one job's: its one-line error, prefixed with the job's
// name (the input, or FILE:LINE), the other jobs still rendered, and at the end
// "N of M jobs failed" and the worst exit code seen (3 over 2 over 1).
// On a terminal with more than one job, a progress bar with an ETA.
//
//   if (wants_batch(args)) return run_batch(args);
#pragma once
#include <filesystem>

namespace ms {

struct RenderArgs;

// Several inputs, --output-dir or --jobs.
bool wants_batch(const RenderArgs& args);

int run_batch(const RenderArgs& args);

// Where a batch writes a positional input (or a job line without
// "output"): <--output-dir>/<stem>.<--format>.
std::filesystem::path batch_output(const RenderArgs& args, const std::filesystem::path& input);

}  // namespace ms
