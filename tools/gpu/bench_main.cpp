// marchstudio-gpubench: `marchstudio bench` alone, for machines without the
// full dependency set (see tools/gpu/CMakeLists.txt).
#include <CLI/CLI.hpp>

#include <cstdio>

#include "cli/bench_cmd.h"
#include "core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"marchstudio bench, lean GPU build", "marchstudio-gpubench"};
  ms::BenchArgs args;
  CLI::App* bench = ms::add_bench_command(app, args);
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ms::Error& e) {  // a flag's value parsed as it is read (--size, --dispatch)
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    return static_cast<int>(e.code());
  }
  try {
    if (bench->parsed()) return ms::run_bench_command(args);
  } catch (const ms::Error& e) {
    std::fprintf(stderr, "marchstudio: %s\n", e.what());
    return static_cast<int>(e.code());
  }
  return 2;
}
