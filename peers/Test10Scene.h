#pragma once

// test10's launch rule and scan as the peers run them: the geometry, the
// outcome rule and the scan steps are test10's own (tests/shared/).

#include "../tests/shared/LaunchOutcome.h"
#include "../tests/shared/VelocityScan.h"

namespace odelab::peers::test10 {

using namespace odelab::scene::test10;

// test10's launch rule (launchOutcome) and scan steps (VelocityScan), as the
// ODE program runs them: the library's own, not copies.
constexpr double SCAN_LIMIT = DEFAULT_SCAN_LIMIT;

}  // namespace odelab::peers::test10
