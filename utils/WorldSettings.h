#pragma once

#include <ode/ode.h>

#include <string>
#include <vector>

namespace odelab {

// The thesis's gravity constant (m/s^2), not the usual 9.81.
constexpr double SURFACE_GRAVITY = 9.823;

enum class Solver { QuickStep, WorldStep };

const char* solverName(Solver solver);  // "quick" or "step", as on the command line

// Valid range of a tunable parameter. The same ranges validate command-line
// values and clamp F-key changes, so both paths agree on what is legal.
struct ParameterRange {
  const char* name;
  double min;
  double max;
  bool contains(double value) const;  // false for NaN
  double clamp(double value) const;
};

namespace ranges {
extern const ParameterRange ERP;
extern const ParameterRange CFM;
extern const ParameterRange STEP;
extern const ParameterRange ITERATIONS;
extern const ParameterRange SOR;
}  // namespace ranges

// Plain data: everything the world step depends on. Scenes override the
// defaults they need; the command line and the F-keys edit it.
struct WorldSettings {
  double erp = 0.2;
  double cfm = 1e-6;
  double step = 0.001;
  int iterations = 20;
  double sor = 1.3;
  Solver solver = Solver::QuickStep;
  double gravity = SURFACE_GRAVITY;  // magnitude, pointing along -y

  void applyTo(dWorldID world) const;
};

// The F2-F8 behaviour: F2 picks the increment used by F3/F4; F6-F8 walk
// through preset ladders. Every change is clamped to its ParameterRange.
class ParameterStepper {
 public:
  ParameterStepper();

  void cycleIncrement(int direction);  // F2 / Shift+F2
  double increment() const { return increments_[incrementIndex_]; }

  void stepErp(WorldSettings& settings, int direction) const;   // F3
  void stepCfm(WorldSettings& settings, int direction) const;   // F4
  static void stepIterations(WorldSettings& settings, int direction);  // F6
  static void stepSor(WorldSettings& settings, int direction);         // F7
  static void stepStepSize(WorldSettings& settings, int direction);    // F8

  // The next value after `current` in an ascending ladder (direction +1) or
  // the previous one (-1); stays at the ends.
  static double nextOnLadder(const std::vector<double>& ladder, double current, int direction);

 private:
  std::vector<double> increments_;
  size_t incrementIndex_;
};

}  // namespace odelab
