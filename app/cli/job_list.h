// `render --jobs FILE`: a JSON-lines job list, one still per line, each an
// object whose keys are render's long flags without the dashes:
//
//   {"scene": "scenes/seed.toml", "output": "out/a.png", "size": "320x180", "set": ["camera.fov=30"]}
//
// The command line's flags are every job's defaults: a scalar key (size,
// spp, time, preset, ...) replaces the flag's value, a list key (set,
// uniform, define, disable, aov, allow-include) adds to the flag's values,
// after them (so a job's --set of a key the command line also sets wins).
// Paths in a line (scene, shader-dir, media-dir, allow-include) are
// relative to the job file's directory, so a list means the same from any
// working directory; a relative "output" is under --output-dir when it is
// given (job_output()). A line without "output" is named as the batch names
// positional inputs (cli/batch.h). Blank lines are skipped.
//
// A bad line (not JSON, an unknown key, a value of the wrong type or out of
// range, over 1 MiB) is not fatal: its entry carries the one-line error,
// blamed on FILE:LINE and the key, and the batch renders the others.
//
// The file is read a line at a time and each job made as it is read, so a
// batch renders its first job before it reads the second line, and holds
// one line (at most 1 MiB: a longer one is skipped, not kept) whatever the
// file's length.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cli/render_job.h"
#include "core/error.h"
#include "pipeline/mesh_job.h"

namespace ms {

struct RenderArgs;

// One job of a batch, or why it cannot be one.
struct BatchEntry {
  std::string label;             // "jobs.jsonl:3", or the input as given
  std::optional<FrameJob> job;   // a still; empty for a mesh or when `error` says why
  std::optional<MeshJob> mesh;   // a mesh line's
  std::optional<Error> error;
  const std::filesystem::path& output() const { return mesh ? mesh->output : job->output; }
};

// The output a job without "output" gets, from its input.
using DefaultOutput = std::function<std::filesystem::path(const std::filesystem::path& input)>;

class JobFile {
 public:
  // Opens `file`: bad_input when it is not a regular file, system when it
  // cannot be opened.
  JobFile(const std::filesystem::path& file, const RenderArgs& defaults, DefaultOutput default_output);
  ~JobFile();
  JobFile(const JobFile&) = delete;
  JobFile& operator=(const JobFile&) = delete;

  // The next non-blank line's entry; empty at the end of the file. Throws
  // system when a read fails.
  std::optional<BatchEntry> next();

  // The non-blank lines of `file`, counted in a pass that keeps none (for
  // a progress bar's total); 0 when it cannot be read.
  static int count_jobs(const std::filesystem::path& file);

 private:
  // The next line into line_ (at most kMaxLineBytes + 1 bytes of it):
  // false at the end of the file.
  bool read_line(bool& too_long);

  std::filesystem::path file_;
  const RenderArgs& defaults_;
  DefaultOutput default_output_;
  int fd_ = -1;
  int number_ = 0;
  std::string line_;
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
};

// Where a job's "output" goes: an absolute path as it is; a relative one
// under `output_dir` (--output-dir) when that is given, else under the job
// file's directory `job_dir`.
std::filesystem::path job_output(const std::filesystem::path& output, const std::filesystem::path& job_dir,
                                 const std::string& output_dir);

// The keys a line may have, for docs and did-you-mean.
const std::vector<std::string>& job_keys();

}  // namespace ms
