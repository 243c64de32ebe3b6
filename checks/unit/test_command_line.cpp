// Option parsing: every common option refuses bad values with a message that
// names the option.
#include <gtest/gtest.h>

#include "CommandLine.h"

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
  odelab::cli::addCommonOptions(app, result.options, result.settings);
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

class CommandLineRejects : public ::testing::TestWithParam<BadValue> {};

TEST_P(CommandLineRejects, NamingTheOption) {
  const Parsed p = parse({GetParam().option, GetParam().value});
  EXPECT_NE(p.error, "") << GetParam().option << " " << GetParam().value << " was accepted";
  EXPECT_NE(p.error.find(GetParam().option), std::string::npos) << p.error;
}

INSTANTIATE_TEST_SUITE_P(
    BadValues, CommandLineRejects,
    ::testing::Values(BadValue{"--step", "0"}, BadValue{"--step", "-0.001"}, BadValue{"--step", "nan"},
                      BadValue{"--step", "inf"}, BadValue{"--step", "abc"}, BadValue{"--step", ""},
                      BadValue{"--erp", "1.5"}, BadValue{"--erp", "-0.1"}, BadValue{"--erp", "nan"},
                      BadValue{"--cfm", "-1e-6"}, BadValue{"--cfm", "nan"}, BadValue{"--cfm", "2"},
                      BadValue{"--iterations", "0"}, BadValue{"--iterations", "2.5"},
                      BadValue{"--iterations", "1e9"}, BadValue{"--sor", "2"}, BadValue{"--sor", "0"},
                      BadValue{"--solver", "fast"}, BadValue{"--seconds", "-1"}, BadValue{"--seconds", "0"},
                      BadValue{"--seconds", "inf"}, BadValue{"--seed", "-3"}, BadValue{"--seed", ""}, BadValue{"--font", ""},
                      BadValue{"--metrics-json", "."}, BadValue{"--frames", "0"},
                      BadValue{"--out-dir", "/nonexistent-folder"},
                      BadValue{"--metrics-json", "/nonexistent-folder/m.json"}));

TEST(CommandLine, UnknownOptionIsRefused) {
  const Parsed p = parse({"--no-such-option"});
  EXPECT_NE(p.error.find("--no-such-option"), std::string::npos) << p.error;
}

TEST(CommandLine, ScreenshotNeedsAWindow) {
  const Parsed p = parse({"--headless", "--screenshot", "shot.png"});
  EXPECT_NE(p.error.find("--screenshot"), std::string::npos) << p.error;
}

}  // namespace
