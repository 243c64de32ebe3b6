#include "SpringDamper.h"

#include <limits>

namespace odelab {

SpringDamper springDamperOf(double erp, double cfm, double step) {
  if (cfm <= 0.0) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, true};
  }
  return {erp / (step * cfm), (1.0 - erp) / cfm, false};
}

ErpCfm erpCfmFor(const SpringDamper& spring, double step) {
  if (spring.rigid) return {1.0, 0.0};
  const double denominator = step * spring.kp + spring.kd;
  return {step * spring.kp / denominator, 1.0 / denominator};
}

}  // namespace odelab
