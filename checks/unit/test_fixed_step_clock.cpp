#include <gtest/gtest.h>

#include "FixedStepClock.h"

using odelab::FixedStepClock;

TEST(FixedStepClock, RunsWholeStepsAndCarriesTheRemainder) {
  FixedStepClock clock;
  EXPECT_EQ(clock.advance(0.0025, 0.001), 2);
  EXPECT_NEAR(clock.timeCache(), 0.0005, 1e-15);
  // The carried half step completes with the next frame's half step.
  EXPECT_EQ(clock.advance(0.0005, 0.001), 1);
  EXPECT_NEAR(clock.timeCache(), 0.0, 1e-15);
}

TEST(FixedStepClock, ClampsLongFramesToMaximumElapsedTime) {
  FixedStepClock clock(FixedStepClock::THESIS_MAXIMUM_ELAPSED_TIME);
  // A 1 s hitch runs only 1/100 s of steps: 10 steps of 1 ms.
  EXPECT_EQ(clock.advance(1.0, 0.001), 10);
  EXPECT_LT(clock.timeCache(), 0.001);
}

TEST(FixedStepClock, DefaultClampIsAQuarterSecond) {
  FixedStepClock clock;
  // A 1 s hitch runs 0.25 s of steps (with 1e-12 of slack for rounding).
  EXPECT_NEAR(clock.advance(1.0, 0.001), 250, 1);
  // An ordinary frame is not clamped at all.
  clock.reset();
  EXPECT_NEAR(clock.advance(0.05, 0.001), 50, 1);
}

TEST(FixedStepClock, StepLongerThanAFrameWaitsForEnoughTime) {
  FixedStepClock clock;
  EXPECT_EQ(clock.advance(0.004, 0.005), 0);
  EXPECT_EQ(clock.advance(0.004, 0.005), 1);
  EXPECT_NEAR(clock.timeCache(), 0.003, 1e-15);
}

TEST(FixedStepClock, IgnoresNegativeElapsedAndResets) {
  FixedStepClock clock;
  EXPECT_EQ(clock.advance(-1.0, 0.001), 0);
  clock.advance(0.0005, 0.001);
  clock.reset();
  EXPECT_EQ(clock.timeCache(), 0.0);
}

TEST(FixedStepClock, SixtyFramesOfOneSixtiethRunOneSecondOfSteps) {
  FixedStepClock clock;
  int steps = 0;
  for (int frame = 0; frame < 60; ++frame) steps += clock.advance(1.0 / 60.0, 0.001);
  // The default clamp leaves a 60 Hz frame whole: real time.
  EXPECT_NEAR(steps, 1000, 1);
}

TEST(FixedStepClock, TheThesisClampRunsSixtyHertzAtSixTenthsOfRealTime) {
  FixedStepClock clock(FixedStepClock::THESIS_MAXIMUM_ELAPSED_TIME);
  int steps = 0;
  for (int frame = 0; frame < 60; ++frame) steps += clock.advance(1.0 / 60.0, 0.001);
  // Each 16.7 ms frame is clamped to 10 ms, so 60 frames give 0.6 s of steps.
  EXPECT_NEAR(steps, 600, 1);
}
