#include <gtest/gtest.h>

#include <set>
#include <string>

#include <cmath>
#include <stdexcept>

#include "KeyTable.h"
#include "Knob.h"
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

TEST(Knob, ListsItselfAsJson) {
  double mass = 5000;
  Knob knob = Knob::real("big_mass", "big cube mass", "kg", mass, 1.0, 1e9).withOption("--big-mass", "");
  EXPECT_EQ(knob.json(),
            "{\"name\": \"big_mass\", \"option\": \"--big-mass\", \"key\": \"\", \"min\": 1, \"max\": 1e+09, "
            "\"unit\": \"kg\", \"default\": 5000, \"kind\": \"real\", \"off_at_zero\": false, \"only_with\": \"\", "
            "\"scene_default\": false}");
}

TEST(KeyTable, AKeyBoundTwiceIsAnError) {
  KeyTable keys;
  keys.bind({SDLK_r, "R", "reset", [](int) {}, true});
  EXPECT_THROW(keys.bind({SDLK_r, "R", "again", [](int) {}, true}), std::logic_error);
  keys.replace({SDLK_r, "R", "the scene's reset", [](int) {}, true});
  EXPECT_EQ(keys.find(SDLK_r)->description, "the scene's reset");
  EXPECT_THROW(keys.replace({SDLK_q, "Q", "nothing to replace", [](int) {}, true}), std::logic_error);
}

// The output-file header and the blow-up message are built from the table:
// each row is in both, with its value, once.
TEST(SettingsTable, EveryRowIsInTheOutputHeaderAndTheBlowUpMessage) {
  WorldSettings settings;
  settings.iterations = 37;
  settings.sor = 1.45;
  const auto header = settingsHeader(settings);
  ASSERT_EQ(header.size(), settingsTable().size());
  const std::string message = settingsInForceText(settings);
  for (const SettingSpec& spec : settingsTable()) {
    const std::string value = settingText(spec.id, settingValue(settings, spec.id));
    int rows = 0;
    for (const auto& [key, text] : header)
      if (key == spec.header) {
        ++rows;
        EXPECT_EQ(text.rfind(value, 0), 0u) << key << ": " << text;
      }
    EXPECT_EQ(rows, 1) << spec.header;
    std::string words = spec.inMessage;
    words.replace(words.find('#'), 1, value);
    EXPECT_NE(message.find(words), std::string::npos) << words << " not in" << message;
  }
  EXPECT_EQ(message, " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 37 iterations, SOR w 1.45)");
}
