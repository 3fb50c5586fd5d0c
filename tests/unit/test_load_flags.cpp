// cli/load_flags.h: the one group of loading flags, as each subcommand
// takes it, and its conversion into a job's fields.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <algorithm>

#include <string>
#include <vector>

#include "cli/load_flags.h"
#include "core/error.h"

namespace ms {
namespace {

// Parses `args` (no program name) with the group added as `choice` says;
// false when CLI11 refuses them.
bool parse(LoadFlags& f, const LoadFlagChoice& choice, std::vector<std::string> args) {
  CLI::App app;
  add_load_flags(&app, f, choice);
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError&) {
    return false;
  }
  return true;
}

TEST(LoadFlags, EveryFlagOfTheGroupLandsInTheJob) {
  LoadFlags f;
  ASSERT_TRUE(parse(f, {}, {"-D", "STEPS=64", "--preset", "fast", "--disable", "ao,shadows", "--no-specialize",
                            "--graph-eval", "interpreter", "--no-prune", "--set", "camera.fov=30",
                            "--uniform", "uTwist=1.5", "--mouse", "1,2"}));
  FrameJob job;
  set_load_fields(job, f);
  ASSERT_EQ(job.defines.size(), 1u);
  EXPECT_EQ(job.defines[0].first, "STEPS");
  EXPECT_EQ(job.defines[0].second, "64");
  EXPECT_EQ(job.preset, "fast");
  EXPECT_TRUE(job.disable.ao);
  EXPECT_TRUE(job.disable.shadows);
  EXPECT_FALSE(job.disable.reflections);
  EXPECT_EQ(job.specialize, Specialization::generic);
  EXPECT_EQ(job.graph_eval, GraphEval::interpreter);
  EXPECT_FALSE(job.prune);
  ASSERT_EQ(job.set.size(), 1u);
  EXPECT_EQ(job.set[0].flag, "--set camera.fov");
  ASSERT_EQ(job.uniforms.size(), 1u);
  EXPECT_EQ(job.uniforms[0].name, "uTwist");
  ASSERT_EQ(job.shadertoy.mouse.size(), 4u);
  EXPECT_EQ(job.shadertoy.mouse[1], 2.0f);
  EXPECT_FALSE(job.shader_dir.empty());  // resolved: the built-in or MARCH_SHADER_DIR
}

TEST(LoadFlags, ASubcommandTakesOnlyTheFlagsItChose) {
  LoadFlagChoice mesh;
  mesh.disable = false;
  mesh.shadertoy = false;
  LoadFlags f;
  EXPECT_FALSE(parse(f, mesh, {"--disable", "ao"}));
  EXPECT_FALSE(parse(f, mesh, {"--mouse", "1,2"}));
  EXPECT_TRUE(parse(f, mesh, {"-D", "X", "--no-prune"}));
  LoadFlagChoice sweep;
  sweep.defines = false;
  EXPECT_FALSE(parse(f, sweep, {"-D", "X"}));
  sweep.preset_help = "The preset the rows vary around";
  LoadFlags g;
  EXPECT_FALSE(parse(g, sweep, {"--preset", "fastest"}));  // its own help, the shared check
  EXPECT_TRUE(parse(g, sweep, {"--preset", "reference"}));
  EXPECT_EQ(g.preset, "reference");
}

TEST(LoadFlags, ABadValueNamesItsFlag) {
  LoadFlags f;
  f.allow_include = {"/no/such/directory"};
  FrameJob job;
  try {
    set_load_fields(job, f);
    FAIL() << "no throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.info().key, "--allow-include");
  }
}

}  // namespace
}  // namespace ms
