#pragma once

// The measurement scenes' dimensions, masses and launch values: one source
// of truth for the ODE programs, the peer-engine programs (peers/) and the
// lab, which reads them back from the programs' metrics. Units are SI.
//
// Each scene has its own namespace below; keep them apart so that one
// scene's edits never touch another's.

namespace odelab::scene {

// ---- test1: Jumping Balls ----------------------------------------------------
namespace test1 {
// Ball i of BALL_COUNT has restitution i / (BALL_COUNT - 1), from 0 to 1.
constexpr int BALL_COUNT = 50;
constexpr double BALL_RADIUS = 0.15;
constexpr double BALL_MASS = 1.0;          // kg
constexpr double DROP_HEIGHT = 7.0;        // centre above the ground
constexpr double SPACING = 0.4;            // m along x (proposed)
constexpr double BOUNCE_VELOCITY = 0.01;   // m/s: slower impacts do not bounce (thesis)
constexpr double GRAVITY_FACTOR = 0.25;    // x SURFACE_GRAVITY (thesis)
constexpr double MEASURED_FROM_BOUNCE = 0.1;  // balls with e below this are left out of max_rebound_error
constexpr double REST_SPEED = 1e-3;        // m/s: a ball slower than this ...
constexpr double REST_CLEARANCE = 1e-3;    // m: ... and this close to the ground is at rest
constexpr double RUN_SECONDS = 15.0;       // the e = 1 ball's second apex comes at 11.8 s
}  // namespace test1

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

// ---- test3: Domino -----------------------------------------------------------
namespace test3 {
constexpr double DOMINO_THICKNESS = 0.2;  // along the path (proposed)
constexpr double DOMINO_HEIGHT = 2.0;     // (proposed)
constexpr double DOMINO_WIDTH = 1.0;      // across the path (proposed)
constexpr double DOMINO_MASS = 1.0;       // (proposed)
constexpr int DEFAULT_DOMINOES = 60;      // (proposed: 60 or more)
constexpr double DOMINO_SPACING = 1.0;    // centre to centre along the path (proposed): half the height
// Archimedean spiral r = SPIRAL_START_RADIUS + SPIRAL_PITCH * angle / 2 pi,
// walked from the inside out, so any number of dominoes fits.
constexpr double SPIRAL_START_RADIUS = 4.0;  // (proposed) tight enough to look like a spiral, loose
                                             // enough that a 1 m wide plate still hits the next one
constexpr double SPIRAL_PITCH = 2.5;         // m between turns (proposed): more than the plate width
// The first domino starts leaning forward on its leading edge and is pushed:
// without the push, a plate tipping from rest is slower than the 0.1
// thresholds for the first 10 steps and auto-disable would freeze it.
constexpr double FIRST_TILT_DEGREES = 10.0;  // (proposed) past the tipping angle atan(0.2 / 2) = 5.7 degrees
constexpr double FIRST_PUSH = 1.0;           // rad/s about the leading edge (proposed): top moves at 2 m/s
// A domino has fallen once it leans more than this from vertical: far past
// the tipping angle (5.7 degrees), so it cannot stand up again; a fallen
// domino rests on its successor at 50 degrees or more (see doc/tests/test3.md).
constexpr double FALLEN_TILT_DEGREES = 30.0;
constexpr double DEFAULT_MU = 1.0;  // the thesis's usual Coulomb coefficient
constexpr double AUTO_DISABLE_THRESHOLD = 0.1;  // linear (m/s) and angular (rad/s), the thesis's
}  // namespace test3

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
constexpr double PLATFORM_SIDE = 10.0;
constexpr double PLATFORM_THICKNESS = 0.2;  // top face at y = 0
constexpr double SPAWN_HEIGHT = 6.0;       // plate centre when dropped
constexpr double SPAWN_ABOVE_STACK = 1.0;  // (proposed) once the stack nears 6 m, drop this far above its top
constexpr double DEFAULT_SPAWN_INTERVAL = 0.3;  // s, headless (proposed): 50 plates land within 20 s
constexpr int DEFAULT_PLATES = 50;              // headless plate count (proposed)
// A plate has landed once it is older than LANDING_MIN_AGE (so it had time to
// start falling) and slower than LANDED_SPEED; from then on it is part of the stack.
constexpr double LANDING_MIN_AGE = 0.1;  // s
constexpr double LANDED_SPEED = 0.05;    // m/s
// Plates dropped in quick succession (N held down) start at least this far
// apart, centre to centre, so a new plate never overlaps one still falling.
constexpr double MIN_SPAWN_SEPARATION = 2 * PLATE_THICKNESS;
// A disabled plate whose bottom face is this far above the top of the plate
// (or platform) below it is not resting on the stack: auto-disable froze it
// in the air.
constexpr double FROZEN_GAP = 0.01;  // m
}  // namespace test5

// ---- test6: Axis system -------------------------------------------------------
namespace test6 {
// A 5000 kg cube held up by a ball joint above a 1 kg cube resting on the
// ground; the anchor is the centre of the big cube's bottom face.
constexpr double SMALL_SIDE = 1.0;
constexpr double SMALL_MASS = 1.0;
constexpr double BIG_SIDE = 5.0;
constexpr double BIG_MASS = 5000.0;
constexpr double ANCHOR_HEIGHT = 3.0;  // also the centre of the big cube's bottom face
// "Upright" ends at a tilt above this or the centre this far from where it was built.
constexpr double UPRIGHT_TILT_DEGREES = 1.0;
constexpr double UPRIGHT_SIDEWAYS_METRES = 0.05;
constexpr double DEFAULT_SECONDS = 60.0;  // headless run (proposed): the thesis saw a fall within seconds
}  // namespace test6

// ---- test7: Axis system 2 ----------------------------------------------------
namespace test7 {
// From the thesis.
constexpr double ANCHOR_HEIGHT = 10.0;  // ball joint to the static world
constexpr double PIVOT_MASS = 5.0;
constexpr double BIG_MASS = 5000.0;
constexpr double TEST_CUBE_MASS = 100.0;
constexpr double THROW_SPEED = 30.0;
constexpr double THESIS_MAX_ANGULAR_SPEED = 10.0;  // rad/s

// Sizes and the throw (proposed).
constexpr double PIVOT_SIDE = 1.0;
constexpr double BIG_SIDE = 5.0;
constexpr double TEST_CUBE_SIDE = 1.0;
constexpr double THROW_DISTANCE = 10.0;  // from the pivot's centre, level with it

// The pivot hangs with its top-face centre on the fixed anchor; the big cube
// hangs with its top-face centre on the pivot's bottom-face centre.
constexpr double PIVOT_CENTRE_Y = ANCHOR_HEIGHT - PIVOT_SIDE / 2;
constexpr double LOWER_ANCHOR_Y = ANCHOR_HEIGHT - PIVOT_SIDE;
constexpr double BIG_CENTRE_Y = LOWER_ANCHOR_Y - BIG_SIDE / 2;

constexpr int DEFAULT_THROWS = 3;               // headless (proposed)
constexpr double DEFAULT_THROW_INTERVAL = 5.0;  // s between throws, headless (proposed)
}  // namespace test7

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
// The scene as built, as metrics under one set of names for test10 and its
// peers (the lab and the constants check read them). `Sink` has set(name, value).
template <class Sink>
void reportScene(Sink& m) {
  m.set("cube_half_size_m", CUBE_HALF_SIZE);
  m.set("cube_mass_kg", CUBE_MASS);
  m.set("wall_thickness_m", WALL_THICKNESS);
  m.set("wall_x_m", WALL_X);
  m.set("wall_height_m", WALL_HEIGHT);
  m.set("wall_width_m", WALL_WIDTH);
  m.set("launch_x_m", LAUNCH_X);
  m.set("launch_y_m", LAUNCH_Y);
  m.set("ground_y_m", GROUND_Y);
}
}  // namespace test10

}  // namespace odelab::scene
