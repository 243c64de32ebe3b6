#include <gtest/gtest.h>

#include <ode/ode.h>

#include <CLI/CLI.hpp>
#include <cmath>

#include "ContactChoices.h"
#include "WorldSettings.h"

using namespace odelab;

TEST(ContactChoices, MuIsANumberAtLeastZeroOrInfinity) {
  EXPECT_EQ(ContactChoices::parseMu("1"), 1.0);
  EXPECT_EQ(ContactChoices::parseMu("0"), 0.0);
  EXPECT_TRUE(std::isinf(ContactChoices::parseMu("inf")));
  EXPECT_TRUE(std::isinf(ContactChoices::parseMu("dInfinity")));
  for (const char* bad : {"-1", "-inf", "nan", "abc", "", "1e400"})
    EXPECT_TRUE(std::isnan(ContactChoices::parseMu(bad))) << bad;
}

TEST(ContactChoices, InfinityIsNamedAndWrittenAsMinusOneInMetrics) {
  EXPECT_EQ(ContactChoices::muText(dInfinity), "dInfinity");
  EXPECT_EQ(ContactChoices::muText(0.5), "0.5");
  EXPECT_EQ(ContactChoices::muMetric(dInfinity), -1.0);
  EXPECT_EQ(ContactChoices::muMetric(2.0), 2.0);
}

TEST(ContactChoices, OptionsSetBothAndRefuseOutOfRange) {
  ContactChoices choices{dInfinity};
  CLI::App app;
  choices.addOptions(app);
  const char* argv[] = {"test", "--mu", "0.7", "--max-contacts", "4"};
  app.parse(5, const_cast<char**>(argv));
  EXPECT_EQ(choices.mu, 0.7);
  EXPECT_EQ(choices.contactLimit(), 4);
  for (const char* count : {"0", "65", "2.5"}) {
    ContactChoices other{1.0};
    CLI::App again;
    other.addOptions(again);
    const char* bad[] = {"test", "--max-contacts", count};
    EXPECT_THROW(again.parse(3, const_cast<char**>(bad)), CLI::ParseError) << count;
  }
}

TEST(ContactChoices, TheKeysLadderEndsAtInfinity) {
  const auto& ladder = ContactChoices::muLadder();
  EXPECT_EQ(ParameterStepper::nextOnLadder(ladder, 5.0, +1), dInfinity);
  EXPECT_EQ(ParameterStepper::nextOnLadder(ladder, dInfinity, -1), 5.0);
  EXPECT_EQ(ParameterStepper::nextOnLadder(ladder, 0.0, -1), 0.0);
}
