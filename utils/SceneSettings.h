#pragma once

#include <ode/ode.h>

#include <deque>
#include <string>
#include <vector>

#include "ContactChoices.h"
#include "Knob.h"
#include "SceneParameters.h"
#include "WorldSettings.h"

namespace odelab {

// What a run is tuned by: the world settings of the table (SettingsTable.h)
// with the F2 increment that steps them, the scene's declared knobs with
// their panel rows, and the contact choices of a scene with contacts. Keys,
// panel and command line change them through AbstractWindow, which records
// each change; the front end and the runner read them through
// AbstractWindow::tuning().
class SceneSettings {
 public:
  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }
  // Every declared knob; the runner adds their options (utils/CommandLine.h).
  std::deque<Knob>& knobs() { return knobs_; }
  const std::deque<Knob>& knobs() const { return knobs_; }
  const SceneParameters& parameters() const { return parameters_; }  // the panel's knob rows
  double f2Increment() const { return stepper_.increment(); }
  double contactMu() const { return contact_.mu; }
  int maxContacts() const { return contact_.contactLimit(); }
  // " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 20 iterations, SOR w 1.3)"
  std::string settingsInForce() const;

 protected:
  explicit SceneSettings(WorldSettings defaults) : settings_(defaults) {}

  WorldSettings settings_;
  ParameterStepper stepper_;
  std::deque<Knob> knobs_;  // a deque keeps each knob in place as more are declared
  SceneParameters parameters_;
  std::vector<Knob*> panelKnobs_;  // parameters_'s rows, in order
  ContactChoices contact_{dInfinity};
  bool contactChoicesUsed_ = false;
};

}  // namespace odelab
