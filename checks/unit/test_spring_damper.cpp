#include <gtest/gtest.h>

#include "SpringDamper.h"

using odelab::erpCfmFor;
using odelab::springDamperOf;

TEST(SpringDamper, MatchesTheOdeManualsFormulas) {
  // ERP = h kp / (h kp + kd), CFM = 1 / (h kp + kd)
  const auto spring = springDamperOf(0.2, 1e-5, 0.001);
  EXPECT_FALSE(spring.rigid);
  const double denominator = 0.001 * spring.kp + spring.kd;
  EXPECT_NEAR(0.001 * spring.kp / denominator, 0.2, 1e-12);
  EXPECT_NEAR(1.0 / denominator, 1e-5, 1e-17);
}

TEST(SpringDamper, SameSpringAtAnotherStepNeedsOtherErpAndCfm) {
  const auto spring = springDamperOf(0.2, 1e-5, 0.001);
  const auto same = erpCfmFor(spring, 0.001);
  EXPECT_NEAR(same.erp, 0.2, 1e-12);
  EXPECT_NEAR(same.cfm, 1e-5, 1e-17);
  const auto coarser = erpCfmFor(spring, 0.002);
  EXPECT_GT(coarser.erp, 0.2);
  EXPECT_LT(coarser.cfm, 1e-5);
  EXPECT_NEAR(springDamperOf(coarser.erp, coarser.cfm, 0.002).kp, spring.kp, 1e-6 * spring.kp);
}

TEST(SpringDamper, ZeroCfmIsRigid) { EXPECT_TRUE(springDamperOf(0.4, 0.0, 0.001).rigid); }
