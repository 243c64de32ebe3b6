#pragma once

// test7's scene as the peers build it: test7's own constants
// (tests/shared/SceneConstants.h) and its throw.

#include <cmath>

#include "../tests/shared/SceneConstants.h"
#include "../utils/WorldSettings.h"
#include "Surfaces.h"

namespace odelab::peers::test7 {

using namespace odelab::scene::test7;

// The throw's elevation: sin 2a = g d / v^2, so that the arc comes back to
// the pivot's level at the pivot (test7's throwTestCube).
inline double throwElevation() {
  return 0.5 * std::asin(SURFACE_GRAVITY * THROW_DISTANCE / (THROW_SPEED * THROW_SPEED));
}

}  // namespace odelab::peers::test7
