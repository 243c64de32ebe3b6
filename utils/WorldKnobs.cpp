#include "WorldKnobs.h"

#include <cmath>

namespace odelab {

namespace {

Knob ranged(const ParameterRange& range, std::string label, std::string unit, double& value) {
  return Knob::real(range.name, std::move(label), std::move(unit), value, range.min, range.max);
}

}  // namespace

double nextStepSize(double step, int direction) {
  static const std::vector<double> ladder{1e-5, 2e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3,
                                          2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 1e-1};
  return nextOnLadder(ladder, step, direction);
}

std::vector<Knob> worldKnobs(WorldSettings& s, const F2Increment& increment) {
  const F2Increment* f2 = &increment;
  std::vector<Knob> knobs;
  knobs.push_back(ranged(ranges::ERP, "ERP", "", s.erp)
                      .withOption("--erp", "global error reduction parameter")
                      .withKey(SDLK_F3, "F3", "ERP up by the increment (Shift: down), within [0, 1]")
                      .steppedBy([f2](double erp, int direction) { return erp + direction * f2->value(); })
                      .worldSetting("erp", "ERP #", 1));
  knobs.push_back(ranged(ranges::CFM, "CFM", "", s.cfm)
                      .withOption("--cfm", "global constraint force mixing")
                      .withKey(SDLK_F4, "F4", "CFM up by the increment (Shift: down), within [0, 1]")
                      .steppedBy([f2](double cfm, int direction) {
                        // Going down from a value smaller than the increment lands on
                        // exactly 0, the setting several scenes need, rather than on a
                        // rounding residue.
                        if (direction < 0 && cfm <= f2->value() * (1 + 1e-9)) return 0.0;
                        return cfm + direction * f2->value();
                      })
                      .logarithmic()
                      .worldSetting("cfm", "CFM #", 2));
  knobs.push_back(Knob::integer(ranges::ITERATIONS.name, "iterations", s.iterations,
                                static_cast<int>(ranges::ITERATIONS.min), static_cast<int>(ranges::ITERATIONS.max))
                      .withOption("--iterations", "QuickStep iterations")
                      .withKey(SDLK_F6, "F6", "QuickStep iterations up (Shift: down): 1, 2, 3, 5, 8, 10, 15, 20, 30, 50 ... 1000",
                               {1, 2, 3, 5, 8, 10, 15, 20, 30, 50, 100, 200, 500, 1000})
                      .logarithmic()
                      .worldSetting("iterations", "# iterations", 4));
  knobs.push_back(ranged(ranges::SOR, "SOR w", "", s.sor)
                      .withOption("--sor", "QuickStep SOR over-relaxation w")
                      .withKey(SDLK_F7, "F7", "SOR relaxation w up by 0.05 (Shift: down), within [0.05, 1.95]")
                      // On the 0.05 grid, so repeated presses never accumulate error.
                      .steppedBy([](double w, int direction) { return std::round((w + direction * 0.05) * 20.0) / 20.0; })
                      .worldSetting("sor_w", "SOR w #", 5));
  knobs.push_back(ranged(ranges::STEP, "step", "s", s.step)
                      .withOption("--step", "simulation step size in seconds")
                      .withKey(SDLK_F8, "F8", "step size up (Shift: down): 1e-5, 2e-5, 5e-5 ... 0.1 s")
                      .steppedBy(nextStepSize)
                      .logarithmic()
                      .worldSetting("step_seconds", "step #", 0));
  WorldSettings* settings = &s;
  knobs.push_back(Knob::choice(
                      "solver", "solver", {"quick", "step"}, {"dWorldQuickStep", "dWorldStep"},
                      [settings] { return settings->solver == Solver::QuickStep ? 0 : 1; },
                      [settings](int index) { settings->solver = index == 0 ? Solver::QuickStep : Solver::WorldStep; })
                      .withOption("--solver", "quick (dWorldQuickStep) or step (dWorldStep)")
                      .withKey(SDLK_F9, "F9", "switch solver: dWorldQuickStep / dWorldStep")
                      .worldSetting("solver", "solver #", 3));
  knobs.push_back(ranged(ranges::GRAVITY, "gravity", "m/s^2", s.gravity)
                      .withOption("--gravity", "gravity's magnitude, m/s^2, along -y (a world file: along its own direction; the thesis's 9.823)")
                      .worldSetting("gravity", "", 6));
  return knobs;
}

}  // namespace odelab
