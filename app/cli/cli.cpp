#include "cli/cli.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <exception>
#include <string>
#include <vector>

#include "suite/outcome.h"
#include "cli/bench_cmd.h"
#include "cli/compare_cmd.h"
#include "cli/flag_checks.h"
#include "cli/glslviewer_flags.h"
#include "cli/info_cmd.h"
#include "cli/mesh_cmd.h"
#include "cli/render_cmd.h"
#include "cli/sweep_cmd.h"
#include "cli/test_cmd.h"
#include "cli/view_cmd.h"
#include "core/error.h"
#include "core/utf8.h"
#include "core/version.h"

namespace ms {

namespace {

// Whether the subcommand that ran was given -v.
bool verbose(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands())
    if (const CLI::Option* v = sub->get_option_no_throw("--verbose"); v && v->count() > 0) return true;
  return false;
}

// --exit-codes idiff on the subcommand (compare, test): a flag's value
// refused as it is read is "could not run" (4) there, as every error after
// parsing is.
bool idiff_requested(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands())
    if (const CLI::Option* o = sub->get_option_no_throw("--exit-codes"))
      for (const std::string& r : o->results())
        if (r == "idiff") return true;
  return false;
}

// `marchstudio help [SUBCOMMAND]` is `marchstudio [SUBCOMMAND] --help`;
// `marchstudio waves.frag` (glslViewer's habit) is `marchstudio view
// waves.frag`. Empty when the command line stays as it is.
std::vector<std::string> rewritten_args(int argc, char** argv) {
  if (argc < 2 || (std::string(argv[1]) != "help" && !opens_in_viewer(argv[1]))) return {};
  const bool help = std::string(argv[1]) == "help";
  std::vector<std::string> words = {argv[0]};
  if (!help) words.emplace_back("view");
  for (int i = help ? 2 : 1; i < argc; ++i) words.emplace_back(argv[i]);
  if (help) words.emplace_back("--help");
  return words;
}

}  // namespace

int run_cli(int argc, char** argv) {
  std::vector<std::string> words = rewritten_args(argc, argv);
  std::vector<char*> new_argv;
  if (!words.empty()) {
    for (std::string& w : words) new_argv.push_back(w.data());
    argc = static_cast<int>(new_argv.size());
    argv = new_argv.data();
  }
  CLI::App app{"marchstudio: a GLSL raymarching studio for SDF scenes", "marchstudio"};
  app.set_version_flag("--version", kSoftware);
  app.require_subcommand(1);
  RenderArgs render_args;
  CLI::App* render = add_render_command(app, render_args);
  ViewArgs view_args;
  CLI::App* view = add_view_command(app, view_args);
  BenchArgs bench_args;
  CLI::App* bench = add_bench_command(app, bench_args);
  CompareArgs compare_args;
  CLI::App* compare = add_compare_command(app, compare_args);
  SweepArgs sweep_args;
  CLI::App* sweep = add_sweep_command(app, sweep_args);
  TestArgs test_args;
  CLI::App* test = add_test_command(app, test_args);
  InfoArgs info_args;
  CLI::App* info = add_info_command(app, info_args);
  MeshArgs mesh_args;
  CLI::App* mesh = add_mesh_command(app, mesh_args);
  // After the subcommands, which would inherit it.
  app.footer("A scene or shader file alone, marchstudio FILE (.toml, .glsl, .frag, .fs, .json), opens it in the viewer "
             "as marchstudio view FILE does.");

  if (const std::string bad = unknown_subcommand(app, argc, argv); !bad.empty()) {
    std::fprintf(stderr, "marchstudio: %s (see 'marchstudio --help')\n", bad.c_str());
    return static_cast<int>(Exit::bad_input);
  }
  if (const std::string habit = glslviewer_habit(argc, argv); !habit.empty()) {
    std::fprintf(stderr, "marchstudio: %s\n", habit.c_str());
    return static_cast<int>(Exit::bad_input);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    std::fprintf(stderr, "marchstudio: %s (see 'marchstudio %s --help')\n", explain_extras(app, e).c_str(),
                 app.get_subcommands().empty() ? "" : app.get_subcommands().back()->get_name().c_str());
    return static_cast<int>(Exit::bad_input);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "marchstudio: %s (see 'marchstudio --help')\n", e.what());
    return static_cast<int>(Exit::bad_input);
  } catch (const Error& e) {  // a flag's value parsed as it is read (--set, --mouse, --dispatch)
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    return idiff_requested(app) ? exit_code_for(ExitCodes::idiff, Outcome::error) : static_cast<int>(e.code());
  }

  try {
    if (render->parsed()) return run_render(render_args);
    if (view->parsed()) return run_view(view_args);
    if (bench->parsed()) return run_bench_command(bench_args);
    if (compare->parsed()) return run_compare(compare_args);
    if (sweep->parsed()) return run_sweep_command(sweep_args);
    if (test->parsed()) return run_test(test_args);
    if (info->parsed()) return run_info(info_args);
    if (mesh->parsed()) return run_mesh(mesh_args);
  } catch (const Error& e) {
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    if (!e.info().detail.empty() && verbose(app)) std::fputs(valid_utf8(e.info().detail).c_str(), stderr);
    return static_cast<int>(e.code());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "marchstudio: out of memory\n");
    return static_cast<int>(Exit::system);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "marchstudio: internal error: %s\n", e.what());
    return static_cast<int>(Exit::system);
  }
  return static_cast<int>(Exit::bad_input);
}

int finish_output(int code) {
  std::cout.flush();
  errno = 0;
  const bool out_failed = std::fflush(stdout) != 0 || std::ferror(stdout) || std::cout.fail();
  const int out_errno = errno;
  const bool err_failed = std::fflush(stderr) != 0 || std::ferror(stderr);
  if (code != static_cast<int>(Exit::ok) && code != static_cast<int>(Exit::threshold)) return code;
  if (out_failed) {
    // On stderr, when that still works; the exit code says it either way.
    std::fprintf(stderr, "marchstudio: cannot write to standard output: %s\n",
                 out_errno ? std::strerror(out_errno) : "a write failed, the output is incomplete");
    std::fflush(stderr);
  }
  return out_failed || err_failed ? static_cast<int>(Exit::system) : code;
}

}  // namespace ms
