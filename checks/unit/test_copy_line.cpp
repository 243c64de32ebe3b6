#include <gtest/gtest.h>

#include <ode/ode.h>

#include <deque>
#include <string>

#include "ContactChoices.h"
#include "CopyLine.h"
#include "Knob.h"
#include "WorldKnobs.h"

using namespace odelab;

namespace {
std::string lineOf(const std::deque<Knob>& knobs, std::vector<LineOption> given = {}) {
  return commandLineText("test4", tuningOptions(knobs, 7, given));
}
}  // namespace

TEST(CopyLine, NamesEveryWorldSettingInAFormThatReadsBackExactly) {
  WorldSettings settings;
  settings.erp = 0.1 + 0.2;  // 0.30000000000000004: six digits would read back as another double
  settings.cfm = 0;
  settings.solver = Solver::WorldStep;
  F2Increment increment;
  std::deque<Knob> knobs;
  for (Knob& knob : worldKnobs(settings, increment)) knobs.push_back(std::move(knob));
  EXPECT_EQ(lineOf(knobs), "test4 --erp 0.30000000000000004 --cfm 0 --iterations 20 --sor 1.3 --step 0.001 "
                           "--solver step --gravity 9.823 --seed 7");
}

TEST(CopyLine, WritesContactKnobsAsTheirOwnOptionsWithInfinityAsInf) {
  ContactChoices choices{dInfinity};
  std::deque<Knob> knobs;
  for (Knob& knob : choices.knobs()) knobs.push_back(std::move(knob));
  EXPECT_NE(lineOf(knobs).find(" --mu inf --max-contacts 16 "), std::string::npos);
  choices.mu = 25;  // beyond the panel's slider, as --mu 25 gives it
  EXPECT_NE(lineOf(knobs).find(" --mu 25 "), std::string::npos);
}

TEST(CopyLine, NamesAKnobWithItsValueUnlessNamingItWouldChangeTheRun) {
  double mass = 12345.678901234567, linear = 0.01;
  int plates = 0, throws = 1;
  std::deque<Knob> knobs{
      Knob::real("big_mass", "big cube mass", "kg", mass, 1, 1e9).withOption("--big-mass", ""),
      Knob::real("linear", "linear", "m/s", linear, 0, 1e6).withOption("--linear", "").onlyWith("--auto-disable"),
      Knob::integer("plates", "plates", plates, 1, 100).withOption("--plates", ""),  // 0: the scene's default
      Knob::integer("throws", "throws", throws, 1, 100).withOption("--throws", "").defaultPickedByScene()};
  std::string line = lineOf(knobs);
  EXPECT_NE(line.find(" --big-mass 12345.678901234567 "), std::string::npos) << line;
  EXPECT_EQ(line.find("--linear"), std::string::npos) << "needs --auto-disable: " << line;
  EXPECT_EQ(line.find("--plates"), std::string::npos) << "0 is refused as --plates: " << line;
  EXPECT_EQ(line.find("--throws"), std::string::npos) << "left to the scene while unchanged: " << line;
  throws = 3;
  line = lineOf(knobs, {{"--auto-disable", "", true}});
  EXPECT_NE(line.find(" --linear 0.01 "), std::string::npos) << line;
  EXPECT_NE(line.find(" --throws 3 "), std::string::npos) << line;
  EXPECT_EQ(line.substr(line.size() - 15), " --auto-disable");
}

TEST(CopyLine, QuotesWhatAShellWouldSplit) {
  EXPECT_EQ(commandLineText("test5", {{"--space", "sap"}, {"--out", "a b's"}}), "test5 --space sap --out 'a b'\\''s'");
}
