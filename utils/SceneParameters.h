#pragma once

#include <string>
#include <vector>

namespace odelab {

// A scene's own tunable value (a mass, a launch velocity, a friction
// coefficient) as the control panel shows it. The scene owns the double;
// the panel sets it within [min, max].
struct SceneParameter {
  std::string label;  // "big cube mass"
  std::string unit;   // "kg", "" for none
  double* value;
  double min, max;
  bool logScale = false;  // the panel's slider spans decades
};

class SceneParameters {
 public:
  void add(SceneParameter parameter) { parameters_.push_back(std::move(parameter)); }
  const std::vector<SceneParameter>& all() const { return parameters_; }
  bool valid(int index) const { return index >= 0 && index < static_cast<int>(parameters_.size()); }
  // Sets a value clamped to its range; returns "label from -> to unit", or
  // "" when the value did not change (or the index or value is invalid).
  std::string set(int index, double value);

 private:
  std::vector<SceneParameter> parameters_;
};

}  // namespace odelab
