#pragma once

// test10's scene values as the peers use them. The geometry belongs in
// odelab::scene::test10 of tests/shared/SceneConstants.h, which the branch
// refactoring test10 fills with these very names (CUBE_SIDE, CUBE_MASS,
// WALL_THICKNESS, WALL_X, WALL_HEIGHT, WALL_WIDTH, LAUNCH_X/Y/Z); once both
// are merged, the geometry block below becomes
// `using namespace odelab::scene::test10;`. Until then the constants check
// (checks/peers.cmake) compares the limits (h + t) / step and (h + t/2) / step
// that both programs derive from them, so a difference cannot go unnoticed.

namespace odelab::peers::test10 {

// ---- geometry (to come from SceneConstants.h) ----
constexpr double WALL_THICKNESS = 0.05;  // thesis
constexpr double WALL_X = 0.0;           // centre of the wall (proposed)
constexpr double WALL_HEIGHT = 6.0;      // standing on the ground (proposed)
constexpr double WALL_WIDTH = 6.0;       // along z (proposed)
constexpr double CUBE_SIDE = 0.4;        // thesis
constexpr double CUBE_MASS = 1.0;        // kg, thesis
constexpr double LAUNCH_X = -4.0, LAUNCH_Y = 3.0, LAUNCH_Z = 0.0;  // thesis
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
