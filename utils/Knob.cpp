#include "Knob.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "FormatValue.h"
#include "WorldSettings.h"

namespace odelab {

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

Knob& Knob::upToInfinity(double sliderTop) {
  max = std::numeric_limits<double>::infinity();
  sliderMax = sliderTop;
  return *this;
}

Knob& Knob::optionParsedByOwner() {
  ownParser = true;
  return *this;
}

double Knob::get() const { return count ? *count : *value; }

std::string Knob::set(double newValue) {
  if (std::isnan(newValue)) return {};
  const double from = get();
  double to = offAtZero && newValue <= 0 ? 0.0 : std::min(max, std::max(min, newValue));
  if (count) {
    *count = static_cast<int>(std::lround(to));
    to = *count;
  } else {
    *value = to;
  }
  if (to == from) return {};
  return label + ' ' + formatValue(from) + " -> " + formatValue(to) + (unit.empty() ? "" : " " + unit);
}

double Knob::next(int direction) const {
  if (stepper) return stepper(get(), direction);
  if (ladder.empty()) return get();
  return ParameterStepper::nextOnLadder(ladder, get(), direction);
}

bool Knob::accepts(double candidate) const {
  // Infinity only where the range reaches it (max is infinity).
  if (std::isnan(candidate) || candidate == -std::numeric_limits<double>::infinity()) return false;
  if (offAtZero && candidate == 0) return true;
  if (kind == KnobKind::Integer && candidate != std::floor(candidate)) return false;
  return candidate >= min && candidate <= max;
}

std::string Knob::rangeText() const {
  const auto bound = [](double value) { return std::isinf(value) ? std::string("inf") : jsonNumber(value); };
  const std::string range = "[" + bound(min) + ", " + bound(max) + "]";
  return offAtZero ? "0 (off) or " + range : range;
}

std::string Knob::optionText() const {
  // jsonNumber's text is the shortest that reads back as the same double,
  // which is what CLI11's number parser does with it; counts are whole;
  // infinity as "inf", which the options that take it read.
  return std::isinf(get()) ? "inf" : jsonNumber(get());
}

std::string Knob::effectText() const {
  if (rebuilds) return "rebuilds the scene";
  if (headlessOnly) return "headless runs only";
  return {};
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "null" : value > 0 ? "\"inf\"" : "\"-inf\"";  // JSON has no infinity
  // The shortest text that reads back as the same double.
  for (int digits = 6; digits <= 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) return text;
  }
  return formatValue(value, 17);
}

std::string Knob::json() const {
  return "{\"name\": " + jsonString(name) + ", \"option\": " + jsonString(option) +
         ", \"key\": " + jsonString(keyName) + ", \"min\": " + jsonNumber(min) + ", \"max\": " + jsonNumber(max) +
         ", \"unit\": " + jsonString(unit) + ", \"default\": " + jsonNumber(get()) +
         ", \"kind\": " + jsonString(kind == KnobKind::Integer ? "integer" : kind == KnobKind::Interval ? "interval" : "real") +
         ", \"off_at_zero\": " + (offAtZero ? "true" : "false") + ", \"only_with\": " + jsonString(companion) +
         ", \"scene_default\": " + (sceneDefault ? "true" : "false") + "}";
}

}  // namespace odelab
