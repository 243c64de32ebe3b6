#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace odelab {

// The two contact settings the thesis mostly leaves unstated: Coulomb
// friction mu (ODE's dInfinity means "never slides") and how many contact
// points dCollide may return per colliding pair. Every scene with contacts
// takes them from here (--mu, --max-contacts, keys F / G, the panel), so a
// run's output says which values made its figures.
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

  int contactLimit() const;
  // The ladder F / G walk: 0 ... 5, then dInfinity.
  static const std::vector<double>& muLadder();
  // A number >= 0, or inf / infinity / dInfinity; NaN when the text is neither.
  static double parseMu(const std::string& text);
  // "dInfinity" or the number: for files and command lines, which parseMu reads back.
  static std::string muText(double mu);
  // "infinite" or the number: for the HUD, the notices and the help, which people read.
  static std::string muWords(double mu);
  // mu for a JSON metric, which has no infinity: -1 stands for dInfinity.
  static double muMetric(double mu);
  // The knobs useContactChoices() declares for the panel and rewind; their
  // options are --mu and --max-contacts below, not the knobs' own.
  static constexpr const char* MU_KNOB = "mu";
  static constexpr const char* MAX_CONTACTS_KNOB = "max_contacts";
  // The option of one of those knobs ("--mu"), "" for any other knob.
  static std::string optionOfKnob(const std::string& knobName);
  // A value of one of them as its option reads it back exactly: mu's
  // dInfinity as "inf", a number in its shortest exact form.
  static std::string optionText(double value);
  // The options' help, also the knobs' (the panel's tooltip).
  static constexpr const char* MU_HELP =
      "contact friction coefficient: a number >= 0, or inf for infinite friction (never slides)";
  static constexpr const char* MAX_CONTACTS_HELP = "contact points dCollide may return per colliding pair";
  // --mu and --max-contacts, with the scene's defaults in the help.
  void addOptions(CLI::App& app);
};

}  // namespace odelab
