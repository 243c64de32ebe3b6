#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "Tuning.h"
#include "WorldKnobs.h"

using namespace odelab;

namespace {

// The world settings as a scene holds them: the knobs point into its settings.
struct World {
  Tuning tuning{WorldSettings{}};
  F2Increment f2;
  World() {
    for (Knob& knob : worldKnobs(tuning.settings(), f2)) tuning.knobs().push_back(std::move(knob));
  }
  WorldSettings& settings() { return tuning.settings(); }
  const std::deque<Knob>& knobs() const { return tuning.knobs(); }
  Knob& knob(const std::string& name) {
    for (Knob& k : tuning.knobs())
      if (k.name == name) return k;
    throw std::logic_error("no knob " + name);
  }
  void step(const std::string& name, int direction) {
    Knob& k = knob(name);
    k.set(k.next(direction));
  }
  F2Increment& increment() { return f2; }
  std::string settingsInForce() const { return tuning.settingsInForce(); }
  std::vector<const Knob*> inReportOrder() const { return tuning.inReportOrder(); }
};

}  // namespace

TEST(F2Increment, CyclesBothWays) {
  F2Increment increment;
  EXPECT_DOUBLE_EQ(increment.value(), 1e-2);
  increment.cycle(+1);
  EXPECT_DOUBLE_EQ(increment.value(), 1e-1);
  increment.cycle(+1);
  EXPECT_DOUBLE_EQ(increment.value(), 1e-6);  // wraps
  increment.cycle(-1);
  EXPECT_DOUBLE_EQ(increment.value(), 1e-1);
}

TEST(WorldKnobs, EveryOneHasItsThesisKeyAnOptionAndAHeaderKey) {
  World world;
  std::set<SDL_Keycode> keys;
  for (const Knob& knob : world.knobs()) {
    EXPECT_TRUE(knob.appliesToWorld) << knob.name;
    EXPECT_EQ(knob.group, KnobGroup::World) << knob.name;
    EXPECT_EQ(knob.option.rfind("--", 0), 0u) << knob.name;
    if (knob.key != SDLK_UNKNOWN) {
      EXPECT_TRUE(keys.insert(knob.key).second) << knob.name;
    }
  }
  EXPECT_EQ(world.knob("erp").key, SDLK_F3);
  EXPECT_EQ(world.knob("cfm").key, SDLK_F4);
  EXPECT_EQ(world.knob("iterations").key, SDLK_F6);
  EXPECT_EQ(world.knob("sor").key, SDLK_F7);
  EXPECT_EQ(world.knob("step").key, SDLK_F8);
  EXPECT_EQ(world.knob("solver").key, SDLK_F9);
  EXPECT_EQ(world.knob("step").headerKey(), "step_seconds");
  EXPECT_EQ(world.knob("sor").headerKey(), "sor_w");
}

TEST(WorldKnobs, ErpStepsByTheIncrementWithinZeroOne) {
  World world;
  world.increment().cycle(+1);  // 0.1
  world.settings().erp = 0.95;
  world.step("erp", +1);
  EXPECT_DOUBLE_EQ(world.settings().erp, 1.0);
  world.settings().erp = 0.05;
  world.step("erp", -1);
  EXPECT_DOUBLE_EQ(world.settings().erp, 0.0);
}

TEST(WorldKnobs, CfmGoesDownToExactlyZeroAndNeverNegative) {
  World world;  // increment 0.01
  world.step("cfm", -1);  // from 1e-6
  EXPECT_EQ(world.settings().cfm, 0.0);
  world.step("cfm", -1);
  EXPECT_EQ(world.settings().cfm, 0.0);
  world.step("cfm", +1);
  EXPECT_DOUBLE_EQ(world.settings().cfm, 0.01);
  world.settings().cfm = 0.995;
  world.step("cfm", +1);
  EXPECT_DOUBLE_EQ(world.settings().cfm, 1.0);
}

TEST(WorldKnobs, LaddersMoveToTheNextRungAndStopAtTheEnds) {
  World world;
  world.step("iterations", +1);
  EXPECT_EQ(world.settings().iterations, 30);
  world.settings().iterations = 25;  // off the ladder, as from --iterations 25
  world.step("iterations", -1);
  EXPECT_EQ(world.settings().iterations, 20);
  world.settings().iterations = 1;
  world.step("iterations", -1);
  EXPECT_EQ(world.settings().iterations, 1);
  world.step("step", -1);  // from 0.001
  EXPECT_DOUBLE_EQ(world.settings().step, 5e-4);
  world.settings().step = 0.1;
  world.step("step", +1);
  EXPECT_DOUBLE_EQ(world.settings().step, 0.1);
}

TEST(WorldKnobs, SorStaysOnItsGridWithinRange) {
  World world;
  for (int i = 0; i < 30; ++i) world.step("sor", +1);
  EXPECT_DOUBLE_EQ(world.settings().sor, ranges::SOR.max);
  for (int i = 0; i < 60; ++i) world.step("sor", -1);
  EXPECT_DOUBLE_EQ(world.settings().sor, ranges::SOR.min);
  world.settings().sor = 1.3;
  world.step("sor", +1);
  EXPECT_DOUBLE_EQ(world.settings().sor, 1.35);
}

TEST(WorldKnobs, AKeyPressAndAPanelValueAreClampedAlike) {
  World world;
  Knob& erp = world.knob("erp");
  EXPECT_EQ(erp.set(erp.next(+1)), "ERP 0.2 -> 0.21");
  EXPECT_EQ(erp.set(7.0), "ERP 0.21 -> 1");
  EXPECT_DOUBLE_EQ(world.settings().erp, 1.0);
  Knob& iterations = world.knob("iterations");
  iterations.set(12.6);
  EXPECT_EQ(world.settings().iterations, 13);
  EXPECT_EQ(iterations.set(13), "");
}

TEST(WorldKnobs, TheSolverIsAChoiceOfTwo) {
  World world;
  Knob& solver = world.knob("solver");
  EXPECT_EQ(solver.set(solver.next(+1)), "solver quick -> step");
  EXPECT_EQ(world.settings().solver, Solver::WorldStep);
  EXPECT_EQ(solver.headerText(), "step (dWorldStep)");
  EXPECT_EQ(solver.optionText(), "step");
  EXPECT_EQ(solver.metricValue(), 1.0);
  EXPECT_EQ(solver.parse("quick"), 0.0);
  EXPECT_TRUE(std::isnan(solver.parse("fast")));
  solver.set(0);
  EXPECT_EQ(world.settings().solver, Solver::QuickStep);
}

// The blow-up and ODE error messages name every world setting but gravity,
// step first, each with its value, once.
TEST(WorldKnobs, MessagesNameTheSettingsInForceStepFirst) {
  World world;
  world.settings().iterations = 37;
  world.settings().sor = 1.45;
  EXPECT_EQ(world.settingsInForce(), " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 37 iterations, SOR w 1.45)");
  std::vector<std::string> order;
  for (const Knob* knob : world.inReportOrder()) order.push_back(knob->headerKey());
  EXPECT_EQ(order, (std::vector<std::string>{"step_seconds", "erp", "cfm", "solver", "iterations", "sor_w", "gravity"}));
}
