#pragma once

// test10's outcome rule for one launched cube, for the program and the peer
// engines alike (peers/Measurements.cpp): what "stopped" and "passed
// through" mean, written once.

#include "SceneConstants.h"

namespace odelab::scene::test10 {

// The scan gives up above this velocity unless told otherwise (proposed).
constexpr double DEFAULT_SCAN_LIMIT = 100000.0;  // m/s
// A launch is over when the cube is wholly past the wall, or moves no longer
// toward it on the near side; failing both, after the time it needs to reach
// the wall plus this much (a soft contact, with CFM > 0, may take a while).
constexpr double SETTLE_SECONDS = 0.05;

enum class Outcome { InFlight, Stopped, Passed };

// Passed: the whole cube is beyond the far face. Stopped: on the near side
// of the mid-plane and no longer moving toward the wall (bounced back, or
// fell to the ground short of it). Otherwise still in flight until the time
// it needs to reach the wall plus SETTLE_SECONDS; then its centre decides.
// x, vx: the cube's centre and velocity along x; `elapsed`: simulated
// seconds since its launch at `velocity`.
inline Outcome launchOutcome(double x, double vx, double velocity, double elapsed) {
  if (x - CUBE_HALF_SIZE > WALL_FAR_FACE) return Outcome::Passed;
  if (vx <= 0.0 && x < WALL_X) return Outcome::Stopped;
  const double reachSeconds = (WALL_FAR_FACE + CUBE_HALF_SIZE - LAUNCH_X) / velocity;
  if (elapsed > reachSeconds + SETTLE_SECONDS) return x > WALL_FAR_FACE ? Outcome::Passed : Outcome::Stopped;
  return Outcome::InFlight;
}

}  // namespace odelab::scene::test10
