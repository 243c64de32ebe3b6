#include "Knob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "FormatValue.h"

namespace odelab {

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

}  // namespace

Knob Knob::real(std::string name, std::string label, std::string unit, double& value, double min, double max) {
  Knob knob;
  knob.name = std::move(name);
  knob.label = std::move(label);
  knob.unit = std::move(unit);
  knob.value = &value;
  knob.min = min;
  knob.max = max;
  knob.initial = value;
  return knob;
}

Knob Knob::integer(std::string name, std::string label, int& value, int min, int max) {
  Knob knob;
  knob.name = std::move(name);
  knob.label = std::move(label);
  knob.count = &value;
  knob.min = min;
  knob.max = max;
  knob.kind = KnobKind::Integer;
  knob.initial = value;
  return knob;
}

Knob Knob::interval(std::string name, std::string label, double& value, double min, double max) {
  Knob knob = real(std::move(name), std::move(label), "s", value, min, max);
  knob.kind = KnobKind::Interval;
  return knob;
}

Knob Knob::toggle(std::string name, std::string label, bool& on) {
  Knob knob;
  knob.name = std::move(name);
  knob.label = std::move(label);
  knob.on = &on;
  knob.max = 1;
  knob.kind = KnobKind::Switch;
  knob.initial = knob.get();
  return knob;
}

Knob Knob::choice(std::string name, std::string label, std::vector<std::string> words,
                  std::vector<std::string> odeNames, std::function<int()> get, std::function<void(int)> set) {
  Knob knob;
  knob.name = std::move(name);
  knob.label = std::move(label);
  knob.kind = KnobKind::Choice;
  knob.max = static_cast<double>(words.size()) - 1;
  knob.choices = std::move(words);
  knob.choiceNames = std::move(odeNames);
  knob.read = [get] { return static_cast<double>(get()); };
  knob.write = [set](double index) { set(static_cast<int>(index)); };
  knob.initial = knob.get();
  return knob;
}

Knob& Knob::withOption(std::string optionName, std::string optionHelp) {
  option = std::move(optionName);
  help = std::move(optionHelp);
  return *this;
}

Knob& Knob::withKey(SDL_Keycode keyCode, std::string name, std::string description, std::vector<double> values) {
  key = keyCode;
  keyName = std::move(name);
  keyHelp = std::move(description);
  ladder = std::move(values);
  return *this;
}

Knob& Knob::withLowerKey(SDL_Keycode keyCode, std::string name, std::string description) {
  lowerKey = keyCode;
  lowerKeyName = std::move(name);
  lowerKeyHelp = std::move(description);
  return *this;
}

Knob& Knob::steppedBy(std::function<double(double, int)> next) {
  stepper = std::move(next);
  return *this;
}

Knob& Knob::zeroIsOff() {
  offAtZero = true;
  return *this;
}

Knob& Knob::logarithmic() {
  logScale = true;
  return *this;
}

Knob& Knob::rebuildsScene() {
  rebuilds = true;
  return *this;
}

Knob& Knob::onlyHeadless() {
  headlessOnly = true;
  return *this;
}

Knob& Knob::defaultPickedByScene() {
  sceneDefault = true;
  return *this;
}

Knob& Knob::onlyWith(std::string flag) {
  companion = std::move(flag);
  return *this;
}

Knob& Knob::inGroup(KnobGroup where) {
  group = where;
  return *this;
}

Knob& Knob::upToInfinity(double sliderTop) {
  max = INF;
  sliderMax = sliderTop;
  return *this;
}

Knob& Knob::worldSetting(std::string headerKey, std::string messageWords, int rank) {
  group = KnobGroup::World;
  appliesToWorld = true;
  header = std::move(headerKey);
  inMessage = std::move(messageWords);
  reportRank = rank;
  return *this;
}

double Knob::get() const {
  if (read) return read();
  if (on) return *on ? 1.0 : 0.0;
  return count ? *count : *value;
}

std::string Knob::set(double newValue) {
  if (std::isnan(newValue)) return {};
  const double from = get();
  double to = offAtZero && newValue <= 0 ? 0.0 : std::min(max, std::max(min, newValue));
  if (kind == KnobKind::Choice || kind == KnobKind::Switch || count) to = std::round(to);
  if (write)
    write(to);
  else if (on)
    *on = to > 0;
  else if (count)
    *count = static_cast<int>(to);
  else
    *value = to;
  to = get();
  if (to == from) return {};
  return label + ' ' + words(from) + " -> " + words(to) + (unit.empty() ? "" : " " + unit);
}

double Knob::next(int direction) const {
  if (stepper) return stepper(get(), direction);
  if (kind == KnobKind::Switch) return get() > 0 ? 0.0 : 1.0;
  if (kind == KnobKind::Choice) {
    const int n = static_cast<int>(choices.size());
    return (static_cast<int>(get()) + (direction >= 0 ? 1 : n - 1)) % n;
  }
  if (ladder.empty()) return get();
  return nextOnLadder(ladder, get(), direction);
}

bool Knob::accepts(double candidate) const {
  // Infinity only where the range reaches it (max is infinity).
  if (std::isnan(candidate) || candidate == -INF) return false;
  if (offAtZero && candidate == 0) return true;
  if (kind != KnobKind::Real && kind != KnobKind::Interval && candidate != std::floor(candidate)) return false;
  return candidate >= min && candidate <= max;
}

std::string Knob::words(double v) const {
  if (kind == KnobKind::Switch) return v > 0 ? "on" : "off";
  if (kind == KnobKind::Choice) return choices.at(static_cast<size_t>(v));
  if (std::isinf(v)) return "infinite";
  return formatValue(v);
}

std::string Knob::rangeText() const {
  if (kind == KnobKind::Switch) return "off, or on with the flag";
  if (kind == KnobKind::Choice) {
    std::string text;
    for (size_t i = 0; i < choices.size(); ++i)
      text += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    return text;
  }
  const auto bound = [](double v) { return std::isinf(v) ? std::string("inf") : shortestNumber(v); };
  const std::string range = "[" + bound(min) + ", " + bound(max) + "]";
  return offAtZero ? "0 (off) or " + range : range;
}

std::string Knob::optionText() const {
  // The shortest text that reads back as the same double, which is what the
  // option's parser does with it; counts are whole; infinity as "inf".
  if (kind == KnobKind::Choice || kind == KnobKind::Switch) return words();
  return std::isinf(get()) ? "inf" : shortestNumber(get());
}

std::string Knob::headerText() const {
  const double v = get();
  if (kind == KnobKind::Switch) return words();
  if (kind == KnobKind::Choice) {
    const auto i = static_cast<size_t>(v);
    return choices.at(i) + (i < choiceNames.size() ? " (" + choiceNames[i] + ")" : "");
  }
  // ODE's name for it, which --mu also reads.
  if (std::isinf(v)) return "dInfinity";
  return formatValue(v);
}

double Knob::metricValue() const {
  const double v = get();
  return std::isinf(v) ? -1.0 : v;
}

std::string Knob::effectText() const {
  if (rebuilds) return "rebuilds the scene";
  if (headlessOnly) return "headless runs only";
  return {};
}

double Knob::parse(const std::string& text) const {
  constexpr double NOT_A_VALUE = std::numeric_limits<double>::quiet_NaN();
  if (kind == KnobKind::Choice) {
    const auto at = std::find(choices.begin(), choices.end(), text);
    return at == choices.end() ? NOT_A_VALUE : static_cast<double>(at - choices.begin());
  }
  if (text == "inf" || text == "infinity" || text == "dInfinity") return std::isinf(max) ? INF : NOT_A_VALUE;
  // strtod takes "0x10" as 16, "nan" and "inf" as themselves: a person
  // typing a setting means a decimal number.
  if (text.empty() || text.find_first_of("xXnNiI") != std::string::npos) return NOT_A_VALUE;
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  // Only the names above mean infinity, not a number too large for a double ("1e400").
  if (end != text.c_str() + text.size() || !std::isfinite(number)) return NOT_A_VALUE;
  return number;
}

std::string shortestNumber(double value) {
  for (int digits = 6; digits <= 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) return text;
  }
  return formatValue(value, 17);
}

double nextOnLadder(const std::vector<double>& ladder, double current, int direction) {
  // Not relative at infinity (mu's dInfinity): inf - inf would match no rung.
  const double tolerance = std::isfinite(current) ? 1e-9 * std::fabs(current) : 0.0;
  if (direction > 0) {
    for (double rung : ladder)
      if (rung > current + tolerance) return rung;
    return std::max(current, ladder.back());
  }
  for (auto it = ladder.rbegin(); it != ladder.rend(); ++it)
    if (*it < current - tolerance) return *it;
  return std::min(current, ladder.front());
}

}  // namespace odelab
