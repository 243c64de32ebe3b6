#pragma once

#include <string>
#include <vector>

#include "Knob.h"

namespace odelab {

// A knob (utils/Knob.h) as the control panel shows it: a row made from the
// knob's declaration (label, unit, kind, what a change does); changes go
// through AbstractWindow::changeParameter.
struct SceneParameter {
  const Knob* knob;
  double min, max;  // the row's range: an off-at-zero knob's starts at 0
};

class SceneParameters {
 public:
  void add(SceneParameter parameter) { parameters_.push_back(parameter); }
  const std::vector<SceneParameter>& all() const { return parameters_; }
  bool valid(int index) const { return index >= 0 && index < static_cast<int>(parameters_.size()); }

 private:
  std::vector<SceneParameter> parameters_;
};

}  // namespace odelab
