#pragma once

// test10's launch rule and scan as the peers run them. The geometry is
// test10's own, from odelab::scene::test10 in tests/shared/SceneConstants.h.

#include "../tests/shared/SceneConstants.h"

namespace odelab::peers::test10 {

using namespace odelab::scene::test10;

// ---- test10's launch rule and scan, as the ODE program runs them ----
// A launch is over when the cube is wholly past the wall, or moves no longer
// toward it on the near side; failing both, after the time it needs to reach
// the wall plus this much (test10's rule).
constexpr double SETTLE_SECONDS = 0.05;
// The scan: every 1 m/s up to 1000 m/s, then every 0.1%, up to the limit.
constexpr double SCAN_FINE_STEP = 1.0;
constexpr double SCAN_FINE_LIMIT = 1000.0;
constexpr double SCAN_COARSE_RATIO = 0.001;
constexpr double SCAN_LIMIT = 100000.0;

}  // namespace odelab::peers::test10
