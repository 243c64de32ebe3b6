#pragma once

#include <ode/ode.h>

#include <string>
#include <vector>

namespace odelab {

// The thesis's gravity constant (m/s^2), not the usual 9.81.
constexpr double SURFACE_GRAVITY = 9.823;

enum class Solver { QuickStep, WorldStep };

const char* solverName(Solver solver);  // "quick" or "step", as on the command line

// The range of a world setting (its knob's, utils/WorldKnobs.cpp), named as
// --list-settings names it.
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
extern const ParameterRange GRAVITY;
}  // namespace ranges

// Plain data: everything the world step depends on. Scenes override the
// defaults they need; their knobs (utils/WorldKnobs.cpp) edit it.
struct WorldSettings {
  double erp = 0.2;
  double cfm = 1e-6;
  double step = 0.001;
  int iterations = 20;
  double sor = 1.3;
  Solver solver = Solver::QuickStep;
  double gravity = SURFACE_GRAVITY;  // magnitude (the knob's), m/s^2
  // The unit vector gravity points along: -y in every scene; a world file's own otherwise.
  double down[3] = {0.0, -1.0, 0.0};

  void applyTo(dWorldID world) const;
};

// F2's increment, the step F3 and F4 move ERP and CFM by: 1e-6 ... 0.1,
// cycled. A run's start keeps it, so a replay steps as the run did.
class F2Increment {
 public:
  void cycle(int direction);  // F2 / Shift+F2
  double value() const { return INCREMENTS[index_]; }

 private:
  static constexpr double INCREMENTS[] = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1};
  int index_ = 4;
};

}  // namespace odelab
