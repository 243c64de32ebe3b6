#include "ContactChoices.h"

#include <ode/ode.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <limits>
#include <sstream>

#include "Knob.h"

namespace odelab {

int ContactChoices::contactLimit() const { return maxContacts; }

const std::vector<double>& ContactChoices::muLadder() {
  static const std::vector<double> ladder{0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 5.0, dInfinity};
  return ladder;
}

double ContactChoices::parseMu(const std::string& text) {
  if (text == "inf" || text == "infinity" || text == "dInfinity") return dInfinity;
  double value = 0;
  if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < 0)
    return std::numeric_limits<double>::quiet_NaN();
  return value;
}

std::string ContactChoices::muText(double mu) {
  if (std::isinf(mu)) return "dInfinity";
  std::ostringstream s;
  s << mu;
  return s.str();
}

std::string ContactChoices::muWords(double mu) { return std::isinf(mu) ? "infinite" : muText(mu); }

double ContactChoices::muMetric(double mu) { return std::isinf(mu) ? -1.0 : mu; }

std::string ContactChoices::optionOfKnob(const std::string& knobName) {
  if (knobName == MU_KNOB) return "--mu";
  if (knobName == MAX_CONTACTS_KNOB) return "--max-contacts";
  return {};
}

std::string ContactChoices::optionText(double value) {
  return std::isinf(value) ? "inf" : jsonNumber(value);  // parseMu takes "inf"
}

void ContactChoices::addOptions(CLI::App& app) {
  app.add_option_function<std::string>(
         "--mu", [this](const std::string& text) { mu = parseMu(text); }, MU_HELP)
      ->check(CLI::Validator(
          [](std::string& text) {
            return std::isnan(parseMu(text)) ? "'" + text + "' is not a number >= 0 or inf" : std::string();
          },
          "MU"))
      ->default_str(std::isinf(mu) ? "inf" : muText(mu));
  app.add_option_function<int>(
         "--max-contacts", [this](int count) { maxContacts = count; }, MAX_CONTACTS_HELP)
      ->check(CLI::Range(1, MOST_CONTACTS))
      ->default_str(std::to_string(contactLimit()));
}

}  // namespace odelab
