#include <gtest/gtest.h>

#include <set>
#include <string>

#include <cmath>
#include <stdexcept>

#include "KeyTable.h"
#include "Knob.h"

using namespace odelab;

TEST(Knob, SetClampsAndSaysWhatChanged) {
  double mass = 5000;
  Knob knob = Knob::real("big_mass", "big cube mass", "kg", mass, 1.0, 1e6);
  EXPECT_EQ(knob.set(2e6), "big cube mass 5000 -> 1e+06 kg");
  EXPECT_DOUBLE_EQ(mass, 1e6);
  EXPECT_EQ(knob.set(1e6), "");
  EXPECT_EQ(knob.set(NAN), "");
}

TEST(Knob, AcceptsItsRangeAndNothingPastIt) {
  double interval = 0;
  Knob knob = Knob::interval("spawn_interval", "spawn interval", interval, 1e-6, 10).zeroIsOff();
  EXPECT_TRUE(knob.accepts(0));  // off
  EXPECT_TRUE(knob.accepts(1e-6));
  EXPECT_EQ(knob.rangeText(), "0 (off) or [1e-06, 10]");
  EXPECT_TRUE(knob.accepts(10));
  EXPECT_FALSE(knob.accepts(5e-7));
  EXPECT_FALSE(knob.accepts(10.000001));
  EXPECT_FALSE(knob.accepts(NAN));
  EXPECT_FALSE(knob.accepts(INFINITY));
  int count = 3;
  Knob whole = Knob::integer("dominoes", "dominoes", count, 2, 1000);
  EXPECT_TRUE(whole.accepts(2));
  EXPECT_FALSE(whole.accepts(2.5));
  EXPECT_FALSE(whole.accepts(1));
  EXPECT_EQ(whole.set(7.6), "dominoes 3 -> 8");
}

TEST(Knob, KeyWalksTheLadderWithinTheRange) {
  double mass = 5000;
  Knob knob = Knob::real("big_mass", "big cube mass", "kg", mass, 1.0, 1e6).withKey(SDLK_F5, "F5", "", {500, 5000, 10000});
  EXPECT_DOUBLE_EQ(knob.next(+1), 10000);
  EXPECT_DOUBLE_EQ(knob.next(-1), 500);
}

TEST(Knob, ReachingInfinityTakesItsNamesAndReportsIt) {
  double mu = 1;
  Knob knob = Knob::real("mu", "contact friction mu", "", mu, 0.0, 0.0).upToInfinity(10);
  for (const char* name : {"inf", "infinity", "dInfinity"}) EXPECT_TRUE(std::isinf(knob.parse(name))) << name;
  for (const char* bad : {"", "x", "0x10", "nan", "1e", "-inf"}) EXPECT_TRUE(std::isnan(knob.parse(bad))) << bad;
  knob.set(knob.parse("inf"));
  EXPECT_EQ(knob.headerText(), "dInfinity");  // ODE's name, which --mu reads back
  EXPECT_EQ(knob.optionText(), "inf");
  EXPECT_EQ(knob.words(), "infinite");
  EXPECT_EQ(knob.metricValue(), -1.0);  // JSON has no infinity
  EXPECT_EQ(knob.rangeText(), "[0, inf]");
  double finite = 2;
  Knob bounded = Knob::real("big_mass", "big cube mass", "kg", finite, 1.0, 1e9);
  EXPECT_TRUE(std::isnan(bounded.parse("inf")));
}

TEST(Knob, ShortestNumberReadsBackExactly) {
  for (double v : {0.1 + 0.2, 1e-6, 0.2, 12345.678901234567, 3e-7})
    EXPECT_EQ(std::strtod(shortestNumber(v).c_str(), nullptr), v) << shortestNumber(v);
  EXPECT_EQ(shortestNumber(0.2), "0.2");
}

TEST(KeyTable, AKeyBoundTwiceIsAnError) {
  KeyTable keys;
  keys.bind({SDLK_r, "R", "reset", [](int) {}, true});
  EXPECT_THROW(keys.bind({SDLK_r, "R", "again", [](int) {}, true}), std::logic_error);
  keys.replace({SDLK_r, "R", "the scene's reset", [](int) {}, true});
  EXPECT_EQ(keys.find(SDLK_r)->description, "the scene's reset");
  EXPECT_THROW(keys.replace({SDLK_q, "Q", "nothing to replace", [](int) {}, true}), std::logic_error);
}
