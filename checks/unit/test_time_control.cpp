#include <gtest/gtest.h>

#include "TimeControl.h"

using odelab::FrameLimit;
using odelab::TimeControl;

TEST(TimeControl, SixtyHertzFramesKeepRealTime) {
  TimeControl time;
  int steps = 0;
  for (int frame = 0; frame < 120; ++frame) {
    const int n = time.stepsFor(1.0 / 60.0, 0.001);
    steps += n;
    time.endFrame(1.0 / 60.0, n * 0.001, 0.001, 0.005, 1.0 / 60.0);
  }
  EXPECT_NEAR(steps, 2000, 1);
  EXPECT_NEAR(time.sessionRealTimeFactor(), 1.0, 1e-3);
  EXPECT_NEAR(time.sessionFramesPerSecond(), 60.0, 1e-6);
  EXPECT_EQ(time.limit(), FrameLimit::Pacing);
}

TEST(TimeControl, TheThesisClampSlowsTwentyFiveHertz) {
  TimeControl time;
  time.setMaximumFrameTime(0.01);
  EXPECT_EQ(time.stepsFor(0.04, 0.001), 10);  // a 40 ms frame runs 10 ms of steps
}

TEST(TimeControl, PausedFramesRunNoStepsAndDoNotCountAgainstRealTime) {
  TimeControl time;
  time.endFrame(0.5, 0.5, 0.0, 0.01, 0.0);
  time.setPaused(true);
  EXPECT_EQ(time.stepsFor(0.5, 0.001), 0);
  time.endFrame(0.5, 0.0, 0.0, 0.01, 0.0);
  EXPECT_DOUBLE_EQ(time.sessionRealTimeFactor(), 1.0);
  EXPECT_DOUBLE_EQ(time.sessionWallSeconds(), 1.0);
}

TEST(TimeControl, DroppedStepsNameThePhysicsAsTheLimit) {
  TimeControl time;
  for (int frame = 0; frame < 30; ++frame) {
    time.stepsFor(0.05, 0.001);
    time.dropSteps(10);
    time.endFrame(0.05, 0.04, 0.05, 0.05, 1.0 / 60.0);
  }
  EXPECT_EQ(time.droppedSteps(), 300);
  EXPECT_EQ(time.limit(), FrameLimit::Physics);
  EXPECT_NEAR(time.recentRealTimeFactor(), 0.8, 1e-9);
}

TEST(TimeControl, SlowDrawingNamesTheDrawingAsTheLimit) {
  TimeControl time;
  for (int frame = 0; frame < 30; ++frame) time.endFrame(0.05, 0.05, 0.002, 0.05, 1.0 / 60.0);
  EXPECT_EQ(time.limit(), FrameLimit::Drawing);
  EXPECT_DOUBLE_EQ(time.longestFrameSeconds(), 0.05);
}

TEST(TimeControl, ScaleStaysWithinItsBounds) {
  TimeControl time;
  for (int i = 0; i < 20; ++i) time.faster();
  EXPECT_DOUBLE_EQ(time.scale(), TimeControl::MAX_SCALE);
  for (int i = 0; i < 20; ++i) time.slower();
  EXPECT_DOUBLE_EQ(time.scale(), TimeControl::MIN_SCALE);
}
