#pragma once

#include <ode/ode.h>

#include <deque>
#include <string>
#include <vector>

#include "ContactChoices.h"
#include "Knob.h"
#include "WorldSettings.h"

namespace odelab {

// What a run is tuned by, as one list of knobs (utils/Knob.h): the world
// settings (utils/WorldKnobs.cpp) with F2's increment, the contact choices
// of a scene with contacts, and the scene's own. Keys, panel and command
// line change them through AbstractWindow, whose member it is and which
// records each change (a friend); the front end and the runner read them
// through AbstractWindow::tuning().
class Tuning {
 public:
  explicit Tuning(WorldSettings defaults) : settings_(defaults) {}

  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }
  // Every knob, world settings first; the runner adds their options (utils/CommandLine.h).
  std::deque<Knob>& knobs() { return knobs_; }
  const std::deque<Knob>& knobs() const { return knobs_; }
  double f2Increment() const { return increment_.value(); }
  double contactMu() const { return contact_.mu; }
  int maxContacts() const { return contact_.maxContacts; }
  // " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 20 iterations, SOR w 1.3)":
  // every knob with message words, in report order.
  std::string settingsInForce() const;
  // The world settings in report order (step first), then every other knob
  // as declared: the order of output headers.
  std::vector<const Knob*> inReportOrder() const;

 private:
  friend class AbstractWindow;
  WorldSettings settings_;
  F2Increment increment_;
  std::deque<Knob> knobs_;  // a deque keeps each knob in place as more are declared
  ContactChoices contact_{dInfinity};
  bool contactChoicesUsed_ = false;
};

}  // namespace odelab
