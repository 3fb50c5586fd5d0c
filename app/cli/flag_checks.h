// Checks the subcommands' flags share, so a bad value gets the one-line
// error with a did-you-mean that a bad TOML key gets:
//
//   cmd->add_option("--disable", a.disable)->check(one_of(kEffectNames));
//   marchstudio: --disable: 'shadow' is not one of shadows, reflections, ao, checker-filter (did you mean 'shadows'?)
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace ms {

extern const std::vector<std::string> kBackendNames;  // auto, egl, osmesa
extern const std::vector<std::string> kEffectNames;   // what --disable takes

// A value from `names`, with a did-you-mean for a near miss.
CLI::Validator one_of(std::vector<std::string> names);
// one_of()'s check for a value that arrives without CLI11 (a --jobs
// line's): throws bad_input naming `flag`, with the same message.
void check_one_of(const std::string& value, const std::vector<std::string>& names, const std::string& flag);
// That error, for a value known not to be one of `names`.
[[noreturn]] void fail_not_one_of(const std::string& value, const std::vector<std::string>& names,
                                  const std::string& flag);
// Not the empty string (`--frames ''` is a mistake, not "no frames").
CLI::Validator not_empty();
// A time in seconds: finite and within a 32-bit float, as the scene file's.
CLI::Validator seconds_value();
// A number >= 0, said in those words (CLI11's NonNegativeNumber prints
// DBL_MAX in full as its upper limit).
CLI::Validator non_negative();
// A finite number > 0, said in those words (CLI::PositiveNumber takes
// "nan", and prints DBL_MAX in full).
CLI::Validator positive();

// A hidden option taking a whole number of pixels >= 0. CLI11 leaves a
// hidden option's name out of its own errors ("marchstudio: : 1 required
// ... missing"), so the value is read here and every error names `name`.
CLI::Option* add_hidden_pixels(CLI::App* cmd, const std::string& name, int& value, const std::string& description);

// "unknown subcommand 'rendr' (did you mean 'render'?)" for argv[1] when it
// names no subcommand of `app`; empty when it does (or is a flag).
std::string unknown_subcommand(const CLI::App& app, int argc, char** argv);

// CLI11's "The following arguments were not expected: --sppp" with a
// did-you-mean against the options of the subcommand that was parsed.
std::string explain_extras(const CLI::App& app, const CLI::ExtrasError& e);

}  // namespace ms
