// Option parsing: every common option refuses bad values with a message that
// names the option.
#include <gtest/gtest.h>

#include <cctype>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "CommandLine.h"
#include "WorldKnobs.h"

namespace {

using odelab::RunOptions;
using odelab::WorldSettings;

struct Parsed {
  RunOptions options;
  WorldSettings settings;
  std::string error;  // empty when accepted
};

Parsed parse(std::vector<std::string> args) {
  Parsed result;
  CLI::App app;
  odelab::cli::addCommonOptions(app, result.options);
  // The world settings' options are their knobs' (utils/WorldKnobs.cpp).
  odelab::F2Increment increment;
  std::deque<odelab::Knob> knobs;
  for (odelab::Knob& knob : odelab::worldKnobs(result.settings, increment)) knobs.push_back(std::move(knob));
  odelab::cli::addKnobOptions(app, knobs);
  odelab::cli::rejectEmptyValues(app);
  args.insert(args.begin(), "test");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    odelab::cli::validateRunOptions(result.options);
  } catch (const CLI::ParseError& e) {
    result.error = e.what();
  } catch (const odelab::UsageError& e) {
    result.error = e.what();
  }
  return result;
}

TEST(CommandLine, AcceptsValidValues) {
  const Parsed p = parse({"--headless", "--seconds", "2", "--step", "1e-4", "--erp", "0.4", "--cfm", "0",
                          "--iterations", "50", "--sor", "1.0", "--solver", "step", "--seed", "7"});
  EXPECT_EQ(p.error, "");
  EXPECT_TRUE(p.options.headless);
  EXPECT_DOUBLE_EQ(p.settings.step, 1e-4);
  EXPECT_DOUBLE_EQ(p.settings.erp, 0.4);
  EXPECT_EQ(p.settings.cfm, 0.0);
  EXPECT_EQ(p.settings.iterations, 50);
  EXPECT_EQ(p.settings.solver, odelab::Solver::WorldStep);
  EXPECT_EQ(p.options.seed, 7u);
}

struct BadValue {
  const char* option;
  const char* value;
};

// "--step" "-0.001" -> step_minus0dot001: a readable, unique test name.
std::string caseName(const ::testing::TestParamInfo<BadValue>& info) {
  std::string name;
  for (const char* c = info.param.option + 2; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  name += "_";
  if (!*info.param.value) name += "empty";
  for (const char* c = info.param.value; *c; ++c) {
    if (std::isalnum(static_cast<unsigned char>(*c)))
      name += *c;
    else if (*c == '-')
      name += "minus";
    else if (*c == '.')
      name += "dot";
    else if (*c == '/')
      name += "slash";
    else
      name += "_";
  }
  return name;
}

class CommandLineRejects : public ::testing::TestWithParam<BadValue> {};

TEST_P(CommandLineRejects, NamingTheOption) {
  const Parsed p = parse({GetParam().option, GetParam().value});
  EXPECT_NE(p.error, "") << GetParam().option << " " << GetParam().value << " was accepted";
  EXPECT_NE(p.error.find(GetParam().option), std::string::npos) << p.error;
}

// Every class of bad value for every common option, as the programs get them
// (checks/common_options.cmake runs the same values through test0, end to
// end): numbers empty, out of range, NaN, infinite, beyond a double (1e400),
// text; integers also a fraction and 20 digits; names not in the list;
// folders and files missing, a file where a folder belongs and the reverse,
// a path under a file. An explicit empty path is an error, not "search as
// usual".
INSTANTIATE_TEST_SUITE_P(
    BadValues, CommandLineRejects,
    ::testing::Values(
        BadValue{"--seconds", ""}, BadValue{"--seconds", "0"}, BadValue{"--seconds", "-1"},
        BadValue{"--seconds", "nan"}, BadValue{"--seconds", "inf"}, BadValue{"--seconds", "-inf"},
        BadValue{"--seconds", "1e400"}, BadValue{"--seconds", "abc"}, BadValue{"--seconds", "1e8"},
        BadValue{"--step", ""}, BadValue{"--step", "0"}, BadValue{"--step", "-1"}, BadValue{"--step", "-0.001"},
        BadValue{"--step", "nan"}, BadValue{"--step", "inf"}, BadValue{"--step", "1e400"},
        BadValue{"--step", "abc"}, BadValue{"--step", "1"}, BadValue{"--step", "1e-7"},
        BadValue{"--erp", ""}, BadValue{"--erp", "-0.1"}, BadValue{"--erp", "1.5"}, BadValue{"--erp", "2"}, BadValue{"--erp", "nan"},
        BadValue{"--erp", "inf"}, BadValue{"--erp", "1e400"}, BadValue{"--erp", "abc"},
        BadValue{"--cfm", ""}, BadValue{"--cfm", "-1"}, BadValue{"--cfm", "-1e-6"}, BadValue{"--cfm", "2"},
        BadValue{"--cfm", "nan"}, BadValue{"--cfm", "inf"}, BadValue{"--cfm", "1e400"}, BadValue{"--cfm", "abc"},
        BadValue{"--sor", ""}, BadValue{"--sor", "0"}, BadValue{"--sor", "-1"}, BadValue{"--sor", "2"},
        BadValue{"--sor", "nan"}, BadValue{"--sor", "inf"}, BadValue{"--sor", "abc"},
        BadValue{"--iterations", ""}, BadValue{"--iterations", "0"}, BadValue{"--iterations", "-1"},
        BadValue{"--iterations", "10001"}, BadValue{"--iterations", "1.5"}, BadValue{"--iterations", "1e9"},
        BadValue{"--iterations", "abc"}, BadValue{"--iterations", "99999999999999999999"},
        BadValue{"--solver", ""}, BadValue{"--solver", "fast"}, BadValue{"--solver", "QUICK"},
        BadValue{"--solver", "1"},
        BadValue{"--seed", ""}, BadValue{"--seed", "-1"}, BadValue{"--seed", "1.5"}, BadValue{"--seed", "abc"},
        BadValue{"--seed", "4294967296"}, BadValue{"--seed", "99999999999999999999"},
        BadValue{"--frames", ""}, BadValue{"--frames", "0"}, BadValue{"--frames", "-1"},
        BadValue{"--frames", "1.5"}, BadValue{"--frames", "abc"}, BadValue{"--frames", "99999999999999999999"},
        BadValue{"--width", ""}, BadValue{"--width", "0"}, BadValue{"--width", "63"},
        BadValue{"--width", "16385"}, BadValue{"--width", "-1"}, BadValue{"--width", "abc"},
        BadValue{"--width", "99999999999999999999"},
        BadValue{"--height", ""}, BadValue{"--height", "0"}, BadValue{"--height", "63"},
        BadValue{"--height", "16385"}, BadValue{"--height", "-1"}, BadValue{"--height", "abc"},
        BadValue{"--height", "99999999999999999999"},
        BadValue{"--out-dir", ""}, BadValue{"--out-dir", "/nonexistent-folder"},
        BadValue{"--out-dir", "/etc/passwd"}, BadValue{"--out-dir", "/etc/passwd/x"},
        BadValue{"--metrics-json", ""}, BadValue{"--metrics-json", "/nonexistent-folder/m.json"},
        BadValue{"--metrics-json", "/etc/passwd/m.json"}, BadValue{"--metrics-json", "."},
        BadValue{"--record", ""}, BadValue{"--record", "/nonexistent-folder"}, BadValue{"--record", "/etc/passwd"},
        BadValue{"--events", ""}, BadValue{"--events", "/nonexistent-file.events"},
        BadValue{"--screenshot", ""}, BadValue{"--shader-dir", ""}, BadValue{"--font", ""}),
    caseName);

// Each of these arguments alone is refused, and the message names it (up to its "=").
TEST(CommandLine, MalformedArgumentsAreRefused) {
  for (const std::string argument : {"--no-such-option", "-x", "extra", "--Step=0.01", "--step", "--headless=maybe"}) {
    const Parsed p = parse({argument});
    EXPECT_NE(p.error.find(argument.substr(0, argument.find('='))), std::string::npos)
        << argument << " -> '" << p.error << "'";
  }
}

TEST(CommandLine, AnOptionGivenTwiceIsRefused) {
  const Parsed p = parse({"--seconds=1", "--seconds=2"});
  EXPECT_NE(p.error.find("--seconds"), std::string::npos) << p.error;
}

TEST(CommandLine, UnknownOptionIsRefused) {
  const Parsed p = parse({"--no-such-option"});
  EXPECT_NE(p.error.find("--no-such-option"), std::string::npos) << p.error;
}

TEST(CommandLine, ScreenshotNeedsAWindow) {
  const Parsed p = parse({"--headless", "--screenshot", "shot.png"});
  EXPECT_NE(p.error.find("--screenshot"), std::string::npos) << p.error;
}

TEST(CommandLine, RecordNeedsAWindow) {
  const Parsed p = parse({"--headless", "--record", "."});
  EXPECT_NE(p.error.find("--record"), std::string::npos) << p.error;
}

// Window-only paths that cannot be written are refused when parsing, before
// any window (or display) is needed.
TEST(CommandLine, UnwritableWindowPathsAreRefused) {
  for (const auto& [option, path] : {std::pair<std::string, std::string>{"--screenshot", "/nonexistent-folder/shot.png"},
                                     {"--record", "/nonexistent-folder"}}) {
    const Parsed p = parse({option, path});
    EXPECT_NE(p.error.find(option), std::string::npos) << option << " " << path << " -> '" << p.error << "'";
  }
}

// The one parse every program makes (the ODE programs and the peers): go on,
// 0 after --help, 2 for a refused value or a failed check after the parse.
TEST(CommandLine, ParseCommandLineGivesTheStatusToEndWith) {
  auto run = [](std::vector<const char*> argv, bool failCheck) {
    double step = 0.001;
    CLI::App app;
    app.add_option("--step", step)->check(odelab::cli::finiteRange(1e-7, 0.1));
    odelab::cli::rejectEmptyValues(app);
    argv.insert(argv.begin(), "peer");
    return odelab::cli::parseCommandLine(app, static_cast<int>(argv.size()), const_cast<char**>(argv.data()), [&] {
      if (failCheck) throw odelab::UsageError("--step: refused after the parse");
    });
  };
  EXPECT_FALSE(run({"--step", "0.01"}, false).has_value());
  EXPECT_EQ(run({"--help"}, false), 0);
  EXPECT_EQ(run({"--step", "nan"}, false), 2);
  EXPECT_EQ(run({"--step", ""}, false), 2);
  EXPECT_EQ(run({"--step", "0.01"}, true), 2);
}

}  // namespace
