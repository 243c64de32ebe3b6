#include <gtest/gtest.h>

#include "SceneVisits.h"
#include "SessionTools.h"

using odelab::Metrics;
using odelab::SceneVisits;

namespace {
Metrics figures(double steps, const char* mark) {
  Metrics m;
  m.set("steps", steps);
  m.set(std::string("mark_") + mark + "_steps", steps / 2);
  return m;
}
}  // namespace

// A window that never switched reports as the scene's own program does.
TEST(SceneVisits, OneVisitKeepsItsNames) {
  const Metrics session = SceneVisits{}.session("test2", figures(100, "a"));
  ASSERT_EQ(session.entries().size(), 2u);
  EXPECT_EQ(session.get("steps"), 100);
  EXPECT_FALSE(session.has("visits"));
}

// After switches every visit keeps its figures (marks included) under its
// number and scene, a scene shown twice under two numbers.
TEST(SceneVisits, EveryVisitNamesItsScene) {
  SceneVisits visits;
  visits.add("test3", figures(10, "before"));
  visits.add("test2", figures(20, "between"));
  const Metrics session = visits.session("test3", figures(30, "after"));
  EXPECT_EQ(session.get("visits"), 3);
  EXPECT_EQ(session.get("visit1.test3.steps"), 10);
  EXPECT_EQ(session.get("visit1.test3.mark_before_steps"), 5);
  EXPECT_EQ(session.get("visit2.test2.mark_between_steps"), 10);
  EXPECT_EQ(session.get("visit3.test3.steps"), 30);
  EXPECT_FALSE(session.has("steps"));  // no figure without its scene
}

// Switch requests of one frame add up: two Page Ups are two scenes back;
// Page Down then Page Up is a switch to the scene on screen, made afresh.
TEST(SceneSwitchRequest, RequestsOfOneFrameAddUp) {
  odelab::SessionTools twoUp;
  twoUp.requestSceneSwitch(-1);
  twoUp.requestSceneSwitch(-1);
  EXPECT_TRUE(twoUp.switchRequested());
  EXPECT_EQ(twoUp.switchRequest(), -2);
  odelab::SessionTools downUp;
  downUp.requestSceneSwitch(+1);
  downUp.requestSceneSwitch(-1);
  EXPECT_TRUE(downUp.switchRequested());
  EXPECT_EQ(downUp.switchRequest(), 0);
  odelab::SessionTools none;
  none.requestSceneSwitch(0);  // a click on the scene on screen
  EXPECT_FALSE(none.switchRequested());
}
