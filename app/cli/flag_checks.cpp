#include "cli/flag_checks.h"

#include <cfloat>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "cli/glslviewer_flags.h"
#include "core/error.h"
#include "core/suggest.h"

namespace ms {

const std::vector<std::string> kBackendNames = {"auto", "egl", "osmesa"};
const std::vector<std::string> kEffectNames = {"shadows", "reflections", "ao", "checker-filter", "bloom"};

namespace {

std::string hint_for(const std::string& word, const std::vector<std::string>& names) {
  std::vector<std::string_view> views(names.begin(), names.end());
  const std::string d = did_you_mean(word, views);
  return d.empty() ? "" : " (" + d + ")";
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out;
}

}  // namespace

void fail_not_one_of(const std::string& value, const std::vector<std::string>& names, const std::string& flag) {
  std::vector<std::string_view> views(names.begin(), names.end());
  fail_input("'" + value + "' is not one of " + joined(names), {}, 0, flag, did_you_mean(value, views));
}

void check_one_of(const std::string& value, const std::vector<std::string>& names, const std::string& flag) {
  if (std::find(names.begin(), names.end(), value) == names.end()) fail_not_one_of(value, names, flag);
}

CLI::Validator one_of(std::vector<std::string> names) {
  const std::string desc = "{" + joined(names) + "}";
  return CLI::Validator(
      [names](std::string& v) -> std::string {
        for (const std::string& n : names)
          if (v == n) return {};
        return "'" + v + "' is not one of " + joined(names) + hint_for(v, names);
      },
      desc);
}

CLI::Validator not_empty() {
  return CLI::Validator([](std::string& v) -> std::string { return v.empty() ? "must not be empty" : ""; }, "");
}

CLI::Validator seconds_value() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        char* end = nullptr;
        const double t = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0') return "'" + v + "' is not a number of seconds";
        if (!std::isfinite(t)) return "must be a finite number of seconds";
        if (std::abs(t) > FLT_MAX) return v + " is too large for a 32-bit float";
        return {};
      },
      "SECONDS");
}

namespace {

// A finite number at or above zero, or strictly above it.
CLI::Validator finite_from_zero(bool zero_allowed) {
  return CLI::Validator(
      [zero_allowed](std::string& v) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0' || !std::isfinite(x)) return "'" + v + "' is not a number";
        if (zero_allowed) return x < 0 ? "must be >= 0, got " + v : "";
        return x > 0 ? "" : "must be > 0, got " + v;
      },
      zero_allowed ? "NUMBER >= 0" : "NUMBER > 0");
}

}  // namespace

CLI::Validator non_negative() { return finite_from_zero(true); }

CLI::Validator positive() { return finite_from_zero(false); }

CLI::Option* add_hidden_pixels(CLI::App* cmd, const std::string& name, int& value, const std::string& description) {
  return cmd
      ->add_option_function<std::string>(
          name,
          [name, &value](const std::string& v) {
            char* end = nullptr;
            errno = 0;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty())
              fail_input(name + " needs a number of pixels", {}, 0, name, "e.g. " + name + " 256");
            if (end == v.c_str() || *end != '\0' || errno == ERANGE || n < 0 || n > INT_MAX)
              fail_input(name + " must be a whole number of pixels >= 0, got '" + v + "'", {}, 0, name,
                         "e.g. " + name + " 256");
            value = static_cast<int>(n);
          },
          description)
      ->expected(0, 1)  // a missing value reaches the check above, which names the flag
      ->group("");
}

std::string unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return {};
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == argv[1]) return {};
    names.push_back(sub->get_name());
  }
  std::string out = "unknown subcommand '" + std::string(argv[1]) + "'" + hint_for(argv[1], names) + "; one of " +
                    joined(names);
  // A scene or shader that is not there (one that is opens in the viewer).
  if (is_input_name(argv[1]))
    out += "; to open a file: marchstudio view FILE, or marchstudio render FILE for an image";
  return out;
}

std::string explain_extras(const CLI::App& app, const CLI::ExtrasError& e) {
  // The subcommand that was parsed, else the top level.
  const CLI::App* where = &app;
  for (const CLI::App* sub : app.get_subcommands()) where = sub;
  std::vector<std::string> flags;
  for (const CLI::Option* o : where->get_options()) {
    for (const std::string& n : o->get_lnames()) flags.push_back("--" + n);
    for (const std::string& n : o->get_snames()) flags.push_back("-" + n);
  }
  std::string out = e.what();
  const std::string prefix = "The following argument was not expected: ";
  const std::string prefixes = "The following arguments were not expected: ";
  std::string rest = out.rfind(prefix, 0) == 0 ? out.substr(prefix.size())
                     : out.rfind(prefixes, 0) == 0 ? out.substr(prefixes.size())
                                                   : "";
  if (rest.empty()) return out;
  // A misspelt flag's value comes out as an extra too: name the flag.
  std::string first = rest.substr(0, rest.find(' '));
  for (size_t at = 0; at < rest.size();) {
    const size_t end = std::min(rest.find(' ', at), rest.size());
    if (rest[at] == '-') {
      first = rest.substr(at, end - at);
      break;
    }
    at = end + 1;
  }
  const size_t eq = first.find('=');
  if (eq != std::string::npos) first.resize(eq);
  if (first.empty() || first[0] != '-') return "unexpected argument '" + first + "'";
  return "unknown flag '" + first + "' for '" + where->get_name() + "'" + hint_for(first, flags);
}

}  // namespace ms
