#include "cli/batch.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <new>
#include <optional>
#include <unordered_map>

#include "core/clock.h"
#include "cli/job_list.h"
#include "cli/render_cmd.h"
#include "cli/sequence_cmd.h"
#include "core/error.h"
#include "pipeline/mesh_sequence.h"
#include "pipeline/progress.h"
#include "pipeline/still_job.h"

namespace ms {
namespace fs = std::filesystem;

namespace {

// Flags that make no sense for many stills: refused before anything runs.
void check_batch_flags(const RenderArgs& a) {
  if (wants_sequence(a))
    fail_input("--frames (and --shard, --video, --no-write) render one input's sequence, not a batch", {}, 0,
               "--frames", "run one `render --frames` per input");
  if (!a.output.empty())
    fail_input("-o names one file, and this batch has several", {}, 0, "-o",
               "give --output-dir DIR (each input to DIR/<stem>.<format>), or an \"output\" per line of --jobs");
  if (a.watch) fail_input("--watch renders one input, not a batch", {}, 0, "--watch");
  if (a.print_shader) fail_input("--print-shader prints one input's shader, not a batch's", {}, 0, "--print-shader");
}

// The line printed for a job's error: prefixed with the job's name unless
// the error already starts with it (a bad --jobs line is blamed on FILE:LINE).
std::string job_error_line(const std::string& label, const Error& e) {
  const std::string what = e.what();
  if (what.rfind(label + ":", 0) == 0) return "marchstudio: " + what;
  return "marchstudio: " + label + ": " + what;
}

// The positional inputs' entries; the job file's come one at a time (JobFile).
std::vector<BatchEntry> input_entries(const RenderArgs& a) {
  std::vector<BatchEntry> entries;
  for (const std::string& input : a.inputs) {
    BatchEntry e;
    e.label = input;
    try {
      e.job = make_render_job(a, input, batch_output(a, input));
    } catch (const Error& err) {
      e.error.emplace(err.info());
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

fs::path output_key(const fs::path& output) {
  std::error_code ec;
  fs::path key = fs::weakly_canonical(fs::absolute(output, ec), ec);
  return ec ? output.lexically_normal() : key;
}

// Two inputs writing one file would leave whichever finished last: refused
// before anything renders.
void refuse_shared_outputs(const std::vector<BatchEntry>& entries) {
  std::map<fs::path, const BatchEntry*> by_output;
  for (const BatchEntry& e : entries) {
    if (!e.job) continue;
    const auto [it, fresh] = by_output.emplace(output_key(e.job->output), &e);
    if (!fresh)
      fail_input("'" + e.label + "' and '" + it->second->label + "' would both write " + e.job->output.string(), {},
                 0, "--output-dir",
                 "inputs of a batch need different stems; rename one, or list them in --jobs with an \"output\" each");
  }
}

// The outputs written so far, each with the job that wrote it: a later
// job (a job file's lines are read as they render) writing one fails alone.
class Outputs {
 public:
  void claim(const BatchEntry& e) {
    const auto [it, fresh] = by_output_.emplace(output_key(e.output()).string(), e.label);
    if (!fresh)
      fail_input("'" + it->second + "' already writes " + e.output().string(), {}, 0, {},
                 "give each line of --jobs its own \"output\"");
  }

 private:
  std::unordered_map<std::string, std::string> by_output_;
};

}  // namespace

bool wants_batch(const RenderArgs& a) { return a.inputs.size() > 1 || !a.output_dir.empty() || !a.jobs.empty(); }

fs::path batch_output(const RenderArgs& a, const fs::path& input) {
  const std::string name = input.stem().string() + "." + format_extension(a.format.value_or(ImageFormat::png));
  return a.output_dir.empty() ? fs::path(name) : fs::path(a.output_dir) / name;
}

int run_batch(const RenderArgs& a) {
  check_batch_flags(a);
  std::error_code ec;
  // A missing directory is made with the first file, as -o makes one.
  if (!a.output_dir.empty() && fs::exists(a.output_dir, ec) && !fs::is_directory(a.output_dir, ec))
    fail_input("not a directory", a.output_dir, 0, "--output-dir");
  const std::vector<BatchEntry> inputs = input_entries(a);
  refuse_shared_outputs(inputs);
  std::optional<JobFile> jobs;
  if (!a.jobs.empty()) jobs.emplace(a.jobs, a, [&a](const fs::path& in) { return batch_output(a, in); });

  // Only a terminal's bar needs the total before the end: the job file is
  // counted in a pass that keeps nothing.
  const bool terminal = ::isatty(2) == 1;
  const int expected = static_cast<int>(inputs.size()) + (terminal && jobs ? JobFile::count_jobs(a.jobs) : 0);
  const bool tty = expected > 1 && terminal;
  const bool paths_on_bar = tty && ::isatty(1) == 1;  // one terminal: a path is printed over the bar
  Progress progress(expected, tty, stderr, "images");
  const auto say = [&](const std::string& line) {
    if (tty) progress.line(line.substr(std::string("marchstudio: ").size()));
    else std::fprintf(stderr, "%s\n", line.c_str());
  };
  FrameSession session;
  Outputs outputs;
  int total = 0, failed = 0, worst = 0, meshes = 0;
  const auto render = [&](const BatchEntry& e) {
    const Clock::time_point t0 = Clock::now();
    int code = 0;
    try {
      if (e.error) throw *e.error;
      outputs.claim(e);
      say_removed_temps({e.output()});  // per job: a job file's outputs are known only as it is read
      std::vector<std::string> written{e.output().string()};
      if (e.mesh) {
        const MeshReport r = mesh_scene(*e.mesh, session);
        if (!r.check.ok() && r.format != MeshFormat::vdb)
          say("marchstudio: warning: " + r.output + ": the mesh check found " + r.check.summary());
        if (!r.written.empty()) written = r.written;  // an OBJ's .mtl too, as `mesh` prints
        ++meshes;
      } else {
        render_still_job(*e.job, session);
      }
      if (paths_on_bar) std::fprintf(stderr, "\r\x1b[K");  // the bar redraws below the path
      for (const std::string& w : written) std::printf("%s\n", w.c_str());
      std::fflush(stdout);
    } catch (const Error& err) {
      say(job_error_line(e.label, err));
      if (!err.info().detail.empty() && a.verbose) std::fprintf(stderr, "%s", err.info().detail.c_str());
      code = static_cast<int>(err.code());
    } catch (const std::bad_alloc&) {
      say("marchstudio: " + e.label + ": out of memory");
      code = static_cast<int>(Exit::system);
    }
    if (code != 0) {
      ++failed;
      worst = std::max(worst, code);
    }
    progress.rendered(total++, seconds_since(t0));
  };
  progress.start();
  for (const BatchEntry& e : inputs) render(e);
  if (jobs)
    while (std::optional<BatchEntry> e = jobs->next()) render(*e);
  progress.finish();
  if (total == 0) fail_input("the batch has no jobs", a.jobs, 0, "--jobs", "one JSON object per line");
  if (a.verbose)
    std::fprintf(stderr, "marchstudio: batch: %d images%s, %ld programs compiled, %ld from the cache\n",
                 total - failed - meshes, meshes > 0 ? (", " + std::to_string(meshes) + " meshes").c_str() : "",
                 session.cache().misses(), session.cache().hits());
  if (failed > 0)
    std::fprintf(stderr, "marchstudio: %d of %d job%s failed\n", failed, total, total == 1 ? "" : "s");
  return worst;
}

}  // namespace ms
