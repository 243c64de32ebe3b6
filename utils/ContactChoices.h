#pragma once

#include <string>
#include <vector>

#include "Knob.h"

namespace odelab {

// The two contact settings the thesis mostly leaves unstated: Coulomb
// friction mu (ODE's dInfinity means "never slides") and how many contact
// points dCollide may return per colliding pair. Every scene with contacts
// takes them from here as two knobs (--mu, --max-contacts, keys F / G, the
// panel's Contacts group), so a run's output says which values made its figures.
struct ContactChoices {
  // dCollide's limit per pair in the thesis's programs was 8 "at least";
  // ODE's box-box test can return more, so the default leaves room.
  static constexpr int DEFAULT_MAX_CONTACTS = 16;
  static constexpr int MOST_CONTACTS = 64;
  // The panel's slider for mu is finite; dInfinity stays reachable by
  // --mu inf and the G key's ladder.
  static constexpr double PANEL_MU_MAX = 10.0;

  double mu;  // >= 0, or dInfinity
  int maxContacts = DEFAULT_MAX_CONTACTS;  // 1 ... MOST_CONTACTS

  // The ladder F / G walk: 0 ... 5, then dInfinity.
  static const std::vector<double>& muLadder();
  // "infinite" or the number: for the HUD, the notices and the help, which people read.
  static std::string muWords(double mu);
  // mu for a JSON metric, which has no infinity: -1 stands for dInfinity.
  static double muMetric(double mu);
  // mu and max_contacts as knobs pointing at these fields, in the Contacts group.
  std::vector<Knob> knobs();
};

}  // namespace odelab
