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
// The pendulum shared with test8 (tests/shared/PendulumRig.h builds it): a
// rod and a sphere merged into one body, hinged to the world about z.
constexpr double ANCHOR_HEIGHT = 7.0;  // thesis: hinge anchor [0, 7, 0]
constexpr double ROD_LENGTH = 3.0;     // (proposed) rod [3.0, 0.1, 0.1] from the anchor along +x
constexpr double ROD_THICKNESS = 0.1;  // (proposed)
constexpr double ROD_MASS = 0.1;       // kg (proposed)
constexpr double BOB_RADIUS = 0.3;     // (proposed)
constexpr double BOB_MASS = 0.33;      // kg (proposed: start energy ~29.6 J against the thesis's ~29.4 J)
constexpr double BOB_DISTANCE = 3.3;   // anchor to the bob's centre (proposed)
constexpr double START_DEFLECTION = 1.5707963267948966;  // pi / 2: released horizontal (thesis)
constexpr double RUN_SECONDS = 60.0;   // the thesis's run
}  // namespace test2

// ---- test4: Different Weights ------------------------------------------------
namespace test4 {
constexpr double PLATFORM_SIDE = 10.0;
constexpr double PLATFORM_THICKNESS = 0.2;  // top face at y = 0
constexpr double SMALL_SIDE = 0.5;          // thesis
constexpr double SMALL_MASS = 5.0;          // kg, thesis
constexpr double BIG_SIDE = 5.0;            // thesis
constexpr double DEFAULT_BIG_MASS = 5000.0; // kg, thesis
constexpr double BIG_START_HEIGHT = SMALL_SIDE + BIG_SIDE / 2;  // 3.0: resting on the small cube
// "Held" ends when the big cube's centre leaves the axis by more than this
// sideways, or drops below BIG_FALLEN_HEIGHT (0.1 m below where it starts).
constexpr double SIDEWAYS_LIMIT = 0.5;
constexpr double BIG_FALLEN_HEIGHT = 2.9;
constexpr double RUN_SECONDS = 20.0;
}  // namespace test4

// ---- test5: Lots of same collisions ------------------------------------------
namespace test5 {
constexpr double PLATE_WIDTH = 5.0;       // x and z (thesis: about [5.0, 0.05, 5.0])
constexpr double PLATE_THICKNESS = 0.05;  // y
constexpr double PLATE_MASS = 1.0;        // kg (proposed)
}  // namespace test5

// ---- test8: Hinge stability --------------------------------------------------
namespace test8 {
// test2's pendulum (namespace test2) with a heavy bob.
constexpr double HEAVY_BOB_MASS = 5000.0;  // kg, thesis
constexpr double RUN_SECONDS = 60.0;       // as test2
}  // namespace test8

// ---- test9: Restitution accuracy ---------------------------------------------
namespace test9 {
constexpr double START_HEIGHT = 5.0;      // ball centre above the ground (thesis)
constexpr double BALL_RADIUS = 0.5;       // (proposed)
constexpr double BALL_MASS = 1.0;         // kg (proposed)
constexpr double BOUNCE = 1.0;            // restitution: a perfect bounce (thesis)
constexpr double GRAVITY_FACTOR = 4.0;    // x SURFACE_GRAVITY, for many bounces quickly (thesis)
constexpr double RUN_SECONDS = 25.0;      // about 26 bounces at CFM 0 (one every 0.957 s)
}  // namespace test9

// ---- test10: Maximum velocity ------------------------------------------------
namespace test10 {
}  // namespace test10

}  // namespace odelab::scene
