// How the check tools in checks/ end their command-line parse, so that every
// one answers alike: --help prints the options and exits 0; bad input prints
// "<tool>: error: ..." and exits 2, the status the checks' callers (CMake
// files, scripts) take as "refused" as opposed to a check that failed (1).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace checks {

constexpr int USAGE = 2;

// nullopt when the parse succeeded and the tool goes on; else the status to
// exit with. `checks` runs after the parse for rules across options; it
// throws CLI::ValidationError to refuse.
template <typename Checks>
std::optional<int> parse(CLI::App& app, int argc, char** argv, Checks checks) {
  try {
    app.parse(argc, argv);
    checks();
  } catch (const CLI::Success& done) {  // --help
    return app.exit(done);
  } catch (const CLI::ParseError& error) {
    std::cerr << app.get_name() << ": error: " << error.what() << "\nRun with --help for the options.\n";
    return USAGE;
  }
  return std::nullopt;
}

inline std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  return parse(app, argc, argv, [] {});
}

// Whole numbers are read in decimal only, as atoi read them before: CLI11
// alone would take "010" as octal 8 and "0x10" as 16. A transform (it drops
// the leading zeros), so give it with ->transform(), before any range check.
inline CLI::Validator decimal() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const size_t digits = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
        if (text.size() == digits || text.find_first_not_of("0123456789", digits) != std::string::npos)
          return "'" + text + "' is not a decimal whole number";
        const std::string sign = text[0] == '-' ? "-" : "";
        const size_t first = text.find_first_not_of('0', digits);
        text = first == std::string::npos ? "0" : sign + text.substr(first);
        return "";
      },
      "");
}

// Reads "X0,Y0,X1,Y1" (fractions of an image) into four numbers.
inline CLI::Option* addRegion(CLI::App& app, double (&region)[4], const std::string& help) {
  return app
      .add_option_function<std::string>(
          "--region",
          [&region](const std::string& text) {
            char tail = 0;
            if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &region[0], &region[1], &region[2], &region[3],
                            &tail) != 4)
              throw CLI::ValidationError("--region", "'" + text + "' is not X0,Y0,X1,Y1");
          },
          help)
      ->type_name("X0,Y0,X1,Y1");
}

}  // namespace checks
