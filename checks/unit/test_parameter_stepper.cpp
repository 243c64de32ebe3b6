#include <gtest/gtest.h>

#include <cmath>

#include "WorldSettings.h"

using odelab::ParameterStepper;
using odelab::WorldSettings;

TEST(ParameterStepper, F2CyclesIncrementsBothWays) {
  ParameterStepper stepper;
  EXPECT_DOUBLE_EQ(stepper.increment(), 1e-2);
  stepper.cycleIncrement(+1);
  EXPECT_DOUBLE_EQ(stepper.increment(), 1e-1);
  stepper.cycleIncrement(+1);
  EXPECT_DOUBLE_EQ(stepper.increment(), 1e-6);  // wraps
  stepper.cycleIncrement(-1);
  EXPECT_DOUBLE_EQ(stepper.increment(), 1e-1);
}

TEST(ParameterStepper, ErpIsClampedToZeroOne) {
  ParameterStepper stepper;
  stepper.cycleIncrement(+1);  // 0.1
  WorldSettings s;
  s.erp = 0.95;
  stepper.stepErp(s, +1);
  EXPECT_DOUBLE_EQ(s.erp, 1.0);
  s.erp = 0.05;
  stepper.stepErp(s, -1);
  EXPECT_DOUBLE_EQ(s.erp, 0.0);
}

TEST(ParameterStepper, CfmGoesDownToExactlyZeroAndNeverNegative) {
  ParameterStepper stepper;  // 0.01
  WorldSettings s;
  s.cfm = 1e-6;
  stepper.stepCfm(s, -1);
  EXPECT_EQ(s.cfm, 0.0);
  stepper.stepCfm(s, -1);
  EXPECT_EQ(s.cfm, 0.0);
  stepper.stepCfm(s, +1);
  EXPECT_DOUBLE_EQ(s.cfm, 0.01);
  s.cfm = 0.995;
  stepper.stepCfm(s, +1);
  EXPECT_DOUBLE_EQ(s.cfm, 1.0);
}

TEST(ParameterStepper, LaddersMoveToTheNextRungAndStopAtTheEnds) {
  WorldSettings s;
  s.iterations = 20;
  ParameterStepper::stepIterations(s, +1);
  EXPECT_EQ(s.iterations, 30);
  s.iterations = 25;  // off the ladder, as from --iterations 25
  ParameterStepper::stepIterations(s, -1);
  EXPECT_EQ(s.iterations, 20);
  s.iterations = 1;
  ParameterStepper::stepIterations(s, -1);
  EXPECT_EQ(s.iterations, 1);

  s.step = 0.001;
  ParameterStepper::stepStepSize(s, -1);
  EXPECT_DOUBLE_EQ(s.step, 5e-4);
  s.step = 0.1;
  ParameterStepper::stepStepSize(s, +1);
  EXPECT_DOUBLE_EQ(s.step, 0.1);
}

TEST(ParameterStepper, SorStaysOnItsGridWithinRange) {
  WorldSettings s;
  for (int i = 0; i < 30; ++i) ParameterStepper::stepSor(s, +1);
  EXPECT_DOUBLE_EQ(s.sor, odelab::ranges::SOR.max);
  for (int i = 0; i < 60; ++i) ParameterStepper::stepSor(s, -1);
  EXPECT_DOUBLE_EQ(s.sor, odelab::ranges::SOR.min);
  s.sor = 1.3;
  ParameterStepper::stepSor(s, +1);
  EXPECT_DOUBLE_EQ(s.sor, 1.35);
}

TEST(ParameterRange, RejectsNaN) {
  EXPECT_FALSE(odelab::ranges::ERP.contains(std::nan("")));
  EXPECT_TRUE(odelab::ranges::ERP.contains(0.5));
}
