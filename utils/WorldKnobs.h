#pragma once

#include <vector>

#include "Knob.h"
#include "WorldSettings.h"

namespace odelab {

// The world settings as knobs, in the order the HUD and the panel show
// them: ERP (F3) and CFM (F4) stepped by F2's increment, iterations (F6),
// SOR w (F7) and the step (F8) on ladders, the solver (F9) a choice, and
// gravity. Each points into `settings`; the increment is read when a key
// steps. Headers and messages list them step first (Knob::reportRank).
std::vector<Knob> worldKnobs(WorldSettings& settings, const F2Increment& increment);

// The step F8 moves to from `step` (+1 up, -1 down): 1e-5, 2e-5, 5e-5 ... 0.1 s.
double nextStepSize(double step, int direction);

}  // namespace odelab
