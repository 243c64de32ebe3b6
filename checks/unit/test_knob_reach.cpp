// Which of ODE's world settings reach another engine (utils/KnobReach.h):
// the HUD and the panel grey the others. The notes are those the engines
// write (peers/wasm/src/engines/translate.js, jolt.js).
#include <gtest/gtest.h>

#include "KnobReach.h"

namespace {

const std::vector<std::string> JOLT_NOTES = {
    "Jolt solves with 10 velocity and 2 position iterations, not the world's 20 QuickStep iterations",
    "the world's ERP 0.4 and CFM 0 have no counterpart in Jolt, which corrects penetration and joint error its own way"};
const std::vector<std::string> RAPIER_NOTES = {
    "the world's ERP 0.4 and CFM 0 have no counterpart in Rapier, which corrects penetration and joint error its own way"};

TEST(KnobReach, OdeTakesEverySetting) {
  for (const char* knob : {"erp", "cfm", "iterations", "sor", "solver", "step"})
    EXPECT_EQ(odelab::knobNotReached(knob, "ode", JOLT_NOTES), "") << knob;
}

TEST(KnobReach, AnEnginesNoteSaysWhatItIgnores) {
  EXPECT_NE(odelab::knobNotReached("erp", "jolt", JOLT_NOTES).find("ERP 0.4"), std::string::npos);
  EXPECT_NE(odelab::knobNotReached("cfm", "jolt", JOLT_NOTES), "");
  EXPECT_NE(odelab::knobNotReached("iterations", "jolt", JOLT_NOTES).find("velocity"), std::string::npos);
  // Rapier takes the iteration count: no note, so the row stays.
  EXPECT_EQ(odelab::knobNotReached("iterations", "rapier", RAPIER_NOTES), "");
}

TEST(KnobReach, OdesOwnSolverSettingsNeverReachAnotherEngine) {
  EXPECT_NE(odelab::knobNotReached("sor", "rapier", RAPIER_NOTES), "");
  EXPECT_NE(odelab::knobNotReached("solver", "rapier", RAPIER_NOTES), "");
  // The step and gravity are every engine's.
  EXPECT_EQ(odelab::knobNotReached("step", "rapier", RAPIER_NOTES), "");
  EXPECT_EQ(odelab::knobNotReached("gravity", "jolt", JOLT_NOTES), "");
}

}  // namespace
