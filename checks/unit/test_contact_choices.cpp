#include <gtest/gtest.h>

#include <ode/ode.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <deque>

#include "CommandLine.h"
#include "ContactChoices.h"

using namespace odelab;

TEST(ContactChoices, MuIsANumberAtLeastZeroOrInfinity) {
  ContactChoices choices{1.0};
  const Knob mu = choices.knobs().front();
  EXPECT_EQ(mu.parse("1"), 1.0);
  EXPECT_EQ(mu.parse("0"), 0.0);
  EXPECT_TRUE(std::isinf(mu.parse("inf")));
  EXPECT_TRUE(std::isinf(mu.parse("dInfinity")));
  for (const char* bad : {"-1", "-inf", "nan", "abc", "", "1e400"}) {
    const double value = mu.parse(bad);
    EXPECT_TRUE(std::isnan(value) || !mu.accepts(value)) << bad;
  }
}

TEST(ContactChoices, InfinityIsNamedAndWrittenAsMinusOneInMetrics) {
  ContactChoices choices{dInfinity};
  const Knob mu = choices.knobs().front();
  EXPECT_EQ(mu.headerKey(), "contact_mu");
  EXPECT_EQ(mu.headerText(), "dInfinity");
  EXPECT_EQ(ContactChoices::muWords(dInfinity), "infinite");
  EXPECT_EQ(ContactChoices::muMetric(dInfinity), -1.0);
  EXPECT_EQ(ContactChoices::muMetric(2.0), 2.0);
}

TEST(ContactChoices, OptionsSetBothAndRefuseOutOfRange) {
  ContactChoices choices{dInfinity};
  std::deque<Knob> knobs;
  for (Knob& knob : choices.knobs()) knobs.push_back(std::move(knob));
  CLI::App app;
  cli::addKnobOptions(app, knobs);
  const char* argv[] = {"test", "--mu", "0.7", "--max-contacts", "4"};
  app.parse(5, const_cast<char**>(argv));
  EXPECT_EQ(choices.mu, 0.7);
  EXPECT_EQ(choices.maxContacts, 4);
  for (const char* count : {"0", "65", "2.5"}) {
    ContactChoices other{1.0};
    std::deque<Knob> otherKnobs;
    for (Knob& knob : other.knobs()) otherKnobs.push_back(std::move(knob));
    CLI::App again;
    cli::addKnobOptions(again, otherKnobs);
    const char* bad[] = {"test", "--max-contacts", count};
    EXPECT_THROW(again.parse(3, const_cast<char**>(bad)), CLI::ParseError) << count;
  }
}

TEST(ContactChoices, TheKeysLadderEndsAtInfinity) {
  const auto& ladder = ContactChoices::muLadder();
  EXPECT_EQ(nextOnLadder(ladder, 5.0, +1), dInfinity);
  EXPECT_EQ(nextOnLadder(ladder, dInfinity, -1), 5.0);
  EXPECT_EQ(nextOnLadder(ladder, 0.0, -1), 0.0);
}
