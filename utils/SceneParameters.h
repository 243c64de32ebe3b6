#pragma once

#include <string>
#include <vector>

namespace odelab {

// A knob (utils/Knob.h) as the control panel shows it: a row made from the
// knob's declaration; changes go through AbstractWindow::changeParameter.
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

 private:
  std::vector<SceneParameter> parameters_;
};

}  // namespace odelab
