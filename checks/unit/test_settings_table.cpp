#include <gtest/gtest.h>

#include <set>
#include <string>

#include "SceneParameters.h"
#include "SettingsTable.h"

using namespace odelab;

TEST(SettingsTable, EverySettingHasItsThesisKeyAndAnOption) {
  std::set<SDL_Keycode> keys;
  for (const SettingSpec& spec : settingsTable()) {
    EXPECT_TRUE(keys.insert(spec.key).second) << spec.label;
    EXPECT_EQ(std::string(spec.option).rfind("--", 0), 0u) << spec.label;
    EXPECT_EQ(spec.range == nullptr, spec.id == SettingId::Solver) << spec.label;
  }
  EXPECT_EQ(settingSpec(SettingId::Erp).key, SDLK_F3);
  EXPECT_EQ(settingSpec(SettingId::Cfm).key, SDLK_F4);
  EXPECT_EQ(settingSpec(SettingId::Step).key, SDLK_F8);
  EXPECT_EQ(settingSpec(SettingId::Solver).key, SDLK_F9);
}

TEST(SettingsTable, AKeyPressAndAPanelValueAreClampedAlike) {
  WorldSettings settings;
  ParameterStepper stepper;  // F2 increment 0.01
  const SettingChange up = stepSetting(settings, SettingId::Erp, +1, stepper);
  EXPECT_EQ(up.text(), "ERP 0.2 -> 0.21");
  const SettingChange typed = assignSetting(settings, SettingId::Erp, 7.0);
  EXPECT_DOUBLE_EQ(settings.erp, 1.0);
  EXPECT_EQ(typed.text(), "ERP 0.21 -> 1");
  assignSetting(settings, SettingId::Iterations, 12.6);
  EXPECT_EQ(settings.iterations, 13);
  EXPECT_FALSE(assignSetting(settings, SettingId::Iterations, 13).changed());
}

TEST(SettingsTable, TheSolverIsAChoiceOfTwo) {
  WorldSettings settings;
  ParameterStepper stepper;
  EXPECT_EQ(stepSetting(settings, SettingId::Solver, +1, stepper).text(), "solver quick -> step");
  EXPECT_EQ(settings.solver, Solver::WorldStep);
  assignSetting(settings, SettingId::Solver, 0);
  EXPECT_EQ(settings.solver, Solver::QuickStep);
}

TEST(SceneParameters, SetClampsAndSaysWhatChanged) {
  double mass = 5000;
  SceneParameters parameters;
  parameters.add({"big cube mass", "kg", &mass, 1.0, 1e6, true});
  EXPECT_EQ(parameters.set(0, 2e6), "big cube mass 5000 -> 1e+06 kg");
  EXPECT_DOUBLE_EQ(mass, 1e6);
  EXPECT_EQ(parameters.set(0, 1e6), "");
  EXPECT_EQ(parameters.set(1, 3.0), "");  // no such parameter
  EXPECT_EQ(parameters.set(0, NAN), "");
}
