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
}  // namespace ranges

void WorldSettings::applyTo(dWorldID world) const {
  dWorldSetERP(world, erp);
  dWorldSetCFM(world, cfm);
  dWorldSetQuickStepNumIterations(world, iterations);
  dWorldSetQuickStepW(world, sor);
  dWorldSetGravity(world, 0, -gravity, 0);
}

ParameterStepper::ParameterStepper()
    : increments_{1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1}, incrementIndex_(4) {}

void ParameterStepper::cycleIncrement(int direction) {
  const size_t n = increments_.size();
  incrementIndex_ = (incrementIndex_ + n + (direction >= 0 ? 1 : n - 1)) % n;
}

void ParameterStepper::stepErp(WorldSettings& settings, int direction) const {
  settings.erp = ranges::ERP.clamp(settings.erp + direction * increment());
}

void ParameterStepper::stepCfm(WorldSettings& settings, int direction) const {
  double value = settings.cfm + direction * increment();
  // Going down from a value smaller than the increment lands on exactly 0,
  // the setting several scenes need, rather than on a rounding residue.
  if (direction < 0 && settings.cfm <= increment() * (1 + 1e-9)) value = 0.0;
  settings.cfm = ranges::CFM.clamp(value);
}

double ParameterStepper::nextOnLadder(const std::vector<double>& ladder, double current, int direction) {
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

void ParameterStepper::stepIterations(WorldSettings& settings, int direction) {
  static const std::vector<double> ladder{1, 2, 3, 5, 8, 10, 15, 20, 30, 50, 100, 200, 500, 1000};
  settings.iterations = static_cast<int>(
      ranges::ITERATIONS.clamp(nextOnLadder(ladder, settings.iterations, direction)));
}

void ParameterStepper::stepSor(WorldSettings& settings, int direction) {
  // Round to the 0.05 grid so repeated presses never accumulate error.
  const double next = std::round((settings.sor + direction * 0.05) * 20.0) / 20.0;
  settings.sor = ranges::SOR.clamp(next);
}

void ParameterStepper::stepStepSize(WorldSettings& settings, int direction) {
  static const std::vector<double> ladder{1e-5, 2e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3,
                                          2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 1e-1};
  settings.step = ranges::STEP.clamp(nextOnLadder(ladder, settings.step, direction));
}

}  // namespace odelab
