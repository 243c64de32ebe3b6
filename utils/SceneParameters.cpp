#include "SceneParameters.h"

#include <algorithm>
#include <cmath>

#include "FormatValue.h"

namespace odelab {

std::string SceneParameters::set(int index, double value) {
  if (!valid(index) || std::isnan(value)) return {};
  SceneParameter& p = parameters_[index];
  const double from = *p.value;
  *p.value = std::min(p.max, std::max(p.min, value));
  if (*p.value == from) return {};
  return p.label + ' ' + formatValue(from) + " -> " + formatValue(*p.value) + (p.unit.empty() ? "" : " " + p.unit);
}

}  // namespace odelab
