#include "WorldSettings.h"

#include <algorithm>
#include <cmath>

namespace odelab {

const char* solverName(Solver solver) { return solver == Solver::QuickStep ? "quick" : "step"; }

bool ParameterRange::contains(double value) const { return value >= min && value <= max; }

double ParameterRange::clamp(double value) const { return std::min(max, std::max(min, value)); }

namespace ranges {
const ParameterRange ERP{"erp", 0.0, 1.0};
const ParameterRange CFM{"cfm", 0.0, 1.0};
const ParameterRange STEP{"step", 1e-6, 0.1};
const ParameterRange ITERATIONS{"iterations", 1, 10000};
// SOR over-relaxation diverges at and above 2.
const ParameterRange SOR{"sor", 0.05, 1.95};
// Magnitude: none (0) up to ten times the Earth's.
const ParameterRange GRAVITY{"gravity", 0.0, 100.0};
}  // namespace ranges

void WorldSettings::applyTo(dWorldID world) const {
  dWorldSetERP(world, erp);
  dWorldSetCFM(world, cfm);
  dWorldSetQuickStepNumIterations(world, iterations);
  dWorldSetQuickStepW(world, sor);
  dWorldSetGravity(world, gravity * down[0], gravity * down[1], gravity * down[2]);
}

void F2Increment::cycle(int direction) {
  constexpr int n = sizeof INCREMENTS / sizeof INCREMENTS[0];
  index_ = (index_ + n + (direction >= 0 ? 1 : n - 1)) % n;
}

}  // namespace odelab
