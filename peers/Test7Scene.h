#pragma once

// test7's scene as the peers build it: test7's own constants
// (tests/shared/SceneConstants.h), its throw, and the one surface choice each
// engine has to map. peers/wasm/src/constants.js reads this file too.

#include <cmath>

#include "../tests/shared/SceneConstants.h"
#include "../utils/WorldSettings.h"

namespace odelab::peers::test7 {

using namespace odelab::scene::test7;

// test7's contacts never slide (ODE's mu = dInfinity). No peer's friction
// coefficient takes infinity: every shape gets this one, a friction cone of
// 89.4 degrees (sliding only once the tangential force is 100 times the normal).
constexpr double NO_SLIP_FRICTION = 100.0;

// The throw's elevation: sin 2a = g d / v^2, so that the arc comes back to
// the pivot's level at the pivot (test7's throwTestCube).
inline double throwElevation() {
  return 0.5 * std::asin(SURFACE_GRAVITY * THROW_DISTANCE / (THROW_SPEED * THROW_SPEED));
}

}  // namespace odelab::peers::test7
