#include "ContactChoices.h"

#include <ode/ode.h>

#include <cmath>

#include "FormatValue.h"

namespace odelab {

const std::vector<double>& ContactChoices::muLadder() {
  static const std::vector<double> ladder{0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 5.0, dInfinity};
  return ladder;
}

std::string ContactChoices::muWords(double mu) { return std::isinf(mu) ? "infinite" : formatValue(mu); }

double ContactChoices::muMetric(double mu) { return std::isinf(mu) ? -1.0 : mu; }

std::vector<Knob> ContactChoices::knobs() {
  std::vector<Knob> both;
  both.push_back(Knob::real("mu", "contact friction mu", "", mu, 0.0, 0.0)
                     .upToInfinity(PANEL_MU_MAX)
                     .withOption("--mu", "contact friction coefficient: a number >= 0, or inf for infinite friction "
                                         "(never slides)")
                     .withKey(SDLK_g, "G", "raise the contact friction mu (ladder 0 ... 5, infinite)", muLadder())
                     .withLowerKey(SDLK_f, "F", "lower the contact friction mu (ladder 0 ... 5, infinite)")
                     .inGroup(KnobGroup::Contacts));
  both.back().header = "contact_mu";
  both.push_back(Knob::integer("max_contacts", "contacts per pair", maxContacts, 1, MOST_CONTACTS)
                     .withOption("--max-contacts", "contact points dCollide may return per colliding pair")
                     .inGroup(KnobGroup::Contacts));
  both.back().header = "max_contacts_per_pair";
  return both;
}

}  // namespace odelab
