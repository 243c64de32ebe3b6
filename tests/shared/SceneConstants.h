#pragma once

// The measurement scenes' dimensions, masses and launch values: one source
// of truth for the ODE programs, the peer-engine programs (peers/) and the
// lab, which reads them back from the programs' metrics. Units are SI.
//
// Each scene has its own namespace below; keep them apart so that one
// scene's edits never touch another's.

namespace odelab::scene {

// ---- test2: Pendulum ---------------------------------------------------------
namespace test2 {
}  // namespace test2

// ---- test4: Different Weights ------------------------------------------------
namespace test4 {
}  // namespace test4

// ---- test5: Lots of same collisions ------------------------------------------
namespace test5 {
}  // namespace test5

// ---- test8: Hinge stability --------------------------------------------------
namespace test8 {
}  // namespace test8

// ---- test9: Restitution accuracy ---------------------------------------------
namespace test9 {
}  // namespace test9

// ---- test10: Maximum velocity ------------------------------------------------
namespace test10 {
// The launched cube, from the thesis.
constexpr double CUBE_SIDE = 0.4;
constexpr double CUBE_HALF_SIZE = CUBE_SIDE / 2;
constexpr double CUBE_MASS = 1.0;
// The wall: thickness from the thesis; position and size proposed. A static
// box standing on the ground, centred on x = WALL_X, across the launch line.
constexpr double WALL_THICKNESS = 0.05;
constexpr double WALL_X = 0.0;
constexpr double WALL_HEIGHT = 6.0;  // y 0 to 6
constexpr double WALL_WIDTH = 6.0;   // along z
constexpr double WALL_NEAR_FACE = WALL_X - WALL_THICKNESS / 2;
constexpr double WALL_FAR_FACE = WALL_X + WALL_THICKNESS / 2;
// Where each cube starts (proposed), moving along +x toward the wall.
constexpr double LAUNCH_X = -4.0, LAUNCH_Y = 3.0, LAUNCH_Z = 0.0;
// The ground: the plane y = GROUND_Y, to show which cubes bounced and which passed.
constexpr double GROUND_Y = 0.0;
// World settings from the thesis: they limit how deep a cube may sink into the wall.
constexpr double ERP = 0.3;
constexpr double CFM = 0.0;
constexpr double SURFACE_LAYER = 0.0;
}  // namespace test10

}  // namespace odelab::scene
