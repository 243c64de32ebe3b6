#include <gtest/gtest.h>
#include <ode/ode.h>

#include "OdeMessages.h"

using odelab::OdeMessages;

TEST(OdeMessages, FloodIsRateLimitedAndTheLatestKept) {
  OdeMessages::clear();
  testing::internal::CaptureStderr();
  for (int i = 0; i < 100; ++i) OdeMessages::handleMessage(3, "LCP internal error " + std::to_string(i));
  const std::string printed = testing::internal::GetCapturedStderr();
  // At most five a second reach stderr; the rest are counted.
  EXPECT_LE(std::count(printed.begin(), printed.end(), '\n'), 6);
  EXPECT_GE(OdeMessages::suppressedCount(), 94);
  const auto recent = OdeMessages::recent();
  ASSERT_EQ(recent.size(), 4u);
  EXPECT_NE(recent.back().find("error 99"), std::string::npos);
  OdeMessages::clear();
}

TEST(OdeMessages, OdeErrorsBecomeExceptionsInsteadOfExit) {
  EXPECT_THROW(dError(7, "bad thing %d", 42), odelab::OdeError);
  try {
    dDebug(8, "internal");
  } catch (const odelab::OdeError& e) {
    EXPECT_NE(std::string(e.what()).find("internal"), std::string::npos);
  }
}
