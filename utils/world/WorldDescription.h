#pragma once

// A world as data: everything an engine needs to build and step the scene a
// test program built in ODE, and nothing about how ODE holds it. Written by
// `testN --export-world FILE`, read by `odelab --world FILE` and by every
// engine adapter (peers/). The file format is doc/world-format.md; the JSON
// is read and written in WorldJson.cpp only.
//
// Frames: y up, metres, kilograms, seconds, radians. A quaternion is
// [w, x, y, z]. Bodies and geoms are named by their index in their list.

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace odelab::world {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // w, x, y, z

constexpr int FORMAT_VERSION = 1;
constexpr double INFINITE = std::numeric_limits<double>::infinity();

struct AutoDisable {
  bool on = false;
  double linearThreshold = 0.01;   // m/s
  double angularThreshold = 0.01;  // rad/s
  int steps = 10;
  double time = 0.0;  // s
  int averageSamples = 1;
};

struct Body {
  double mass = 1.0;
  // About the centre of mass, in the body's frame: xx, yy, zz, xy, xz, yz.
  std::array<double, 6> inertia{1, 1, 1, 0, 0, 0};
  Vec3 position{0, 0, 0};  // the centre of mass
  Quat orientation{1, 0, 0, 0};
  Vec3 linearVelocity{0, 0, 0};
  Vec3 angularVelocity{0, 0, 0};
  bool enabled = true;    // false: asleep (auto-disabled) as exported
  bool kinematic = false; // moved only by its velocity, never by forces or contacts
  bool gravity = true;
  double maxAngularSpeed = INFINITE;  // rad/s
  AutoDisable autoDisable;
  bool removed = false;  // in memory only: a body the scene removed while running
};

enum class ShapeKind { Box, Sphere, Plane, Capsule, Cylinder };

struct Geom {
  ShapeKind shape = ShapeKind::Box;
  Vec3 size{1, 1, 1};   // box: sides; sphere: radius in [0]; capsule, cylinder: radius, length (along local z)
  std::array<double, 4> plane{0, 1, 0, 0};  // a, b, c, d of a*x + b*y + c*z = d (plane only)
  int body = -1;        // index in bodies, or -1: static
  // The pose: of a body's geom relative to the body's centre of mass; of a
  // static geom in the world. A plane has none.
  Vec3 position{0, 0, 0};
  Quat orientation{1, 0, 0, 0};
  std::uint32_t category = 0xffffffffu;
  std::uint32_t collide = 0xffffffffu;
};

enum class JointKind { Ball, Hinge, Slider, Fixed };

struct Joint {
  JointKind kind = JointKind::Ball;
  int body1 = -1;  // index in bodies, or -1: the static world
  int body2 = -1;
  Vec3 anchor{0, 0, 0};  // world, as built (ball, hinge)
  Vec3 axis{0, 0, 1};    // world (hinge, slider)
  double lowStop = -INFINITE;  // rad or m (hinge, slider)
  double highStop = INFINITE;
  // The joint's own ERP and CFM; NaN where the joint takes the world's.
  double erp = std::numeric_limits<double>::quiet_NaN();
  double cfm = std::numeric_limits<double>::quiet_NaN();
};

// What ODE's near callback gives a contact between two geoms: its
// dSurfaceParameters, with the mode's flags named.
struct Surface {
  double mu = INFINITE;             // Coulomb friction; INFINITE never slides
  bool bounce = false;
  double restitution = 0.0;         // bounce, 0..1 (when bounce)
  double bounceVelocity = 0.0;      // m/s: slower impacts do not bounce (when bounce)
  bool softErp = false;
  double softErpValue = 0.0;
  bool softCfm = false;
  double softCfmValue = 0.0;
  bool approx1 = false;             // ODE's friction pyramid approximation
  bool operator==(const Surface& o) const;
  bool operator!=(const Surface& o) const { return !(*this == o); }
};

struct PairSurface {
  int geom1 = -1, geom2 = -1;  // geom1 < geom2
  int surface = 0;             // index in surfaces
};

struct Settings {
  double step = 0.001;  // s
  Vec3 gravity{0, -9.823, 0};
  double erp = 0.2;
  double cfm = 1e-5;
  bool quickStep = true;  // false: ODE's dWorldStep (the "big matrix" solver)
  int iterations = 20;    // QuickStep
  double sorW = 1.3;
  double contactMaxCorrectingVelocity = INFINITE;  // m/s
  double contactSurfaceLayer = 0.0;                // m
  int maxContacts = 16;   // contact points per colliding pair
  std::string space = "simple";  // ODE's broad phase: simple, hash, sap, quadtree
};

// What `odelab --world` measures of the run (doc/worlds.md): each kind a
// metric or a few and a HUD line, computed from the bodies' states after every
// step, whichever engine stepped them.
enum class MeasureKind { Energy, Momentum, JointError, Penetration, Tunnelling, Ballistic, Period, Rest, Probe };

// A probe reads one number of one body's state (doc/world-format.md,
// "probe"): what it reads, along which axis, and how the run's readings
// become one figure.
// Energy: the world's mechanical energy (as the energy measure's), of no one body.
enum class ProbeOf { Position, Velocity, Displacement, AngularVelocity, AngularMomentum, Energy };
enum class ProbeTake { At, Max, Min, FirstCrossing };
constexpr int MAGNITUDE = 3;  // a probe's axis: |v| rather than a component

struct Measure {
  MeasureKind kind = MeasureKind::Energy;
  std::string name;      // ballistic, period: the metrics' prefix
  double scale = 0.0;    // energy (J); momentum: linear (kg m/s); 0: from the start state
  double angularScale = 0.0;  // momentum: angular (kg m^2/s); 0: from the start state
  int body = -1;         // ballistic, period
  int geom = -1;         // tunnelling: the thin static geom
  int axis = 0;          // period: the coordinate timed (0 x, 1 y, 2 z)
  double about = 0.0;    // period: the value whose crossings time the swing
  double expected = 0.0; // period: the analytic period, s
  double until = INFINITE;  // ballistic: the arc is compared up to this time, s; probe: the window's end
  double speed = 0.01, angularSpeed = 0.01, hold = 0.5;  // rest: m/s, rad/s, s
  // The analytic answer the world states (the lab grades every engine against
  // it): energy, the energy_drift; tunnelling, the bodies that pass; rest, the
  // time to rest (s). NaN: none stated.
  double expect = std::numeric_limits<double>::quiet_NaN();
  bool expectNever = false;  // rest: the body never comes to rest (it slides on)
  // probe: what it reads (`axis` 0..2 or MAGNITUDE) and how; `at` NaN: the
  // run's last state; `value`: the level a first crossing is timed at.
  ProbeOf of = ProbeOf::Position;
  ProbeTake take = ProbeTake::At;
  double at = std::numeric_limits<double>::quiet_NaN();
  double from = 0.0;  // probe: the window max, min and first_crossing look in, s
  double value = 0.0;
  // probe: the absolute tolerance on `expect` (in the reading's unit), or
  // relative to |expect|; exactly one is set when `expect` is.
  double tolerance = std::numeric_limits<double>::quiet_NaN();
  double relativeTolerance = std::numeric_limits<double>::quiet_NaN();
};

// A timed edit of the world: a body dropped in, or one pushed.
enum class EventKind { Drop, Push };

struct Event {
  double at = 0.0;  // simulated seconds
  EventKind kind = EventKind::Drop;
  int body = 0;
  Vec3 impulse{0, 0, 0};  // push: N s, at the centre of mass
};

// A body's analytic motion, drawn as a ghost beside what the engines make of
// it (doc/world-format.md, "ghost"): every figure of the law comes from the
// world itself (the body's start state, gravity, the ground's surface), so
// the file states only which body and which law. GhostLaw.h computes it.
enum class GhostLaw { Ballistic, Bounce, Pendulum };

struct Ghost {
  bool on = false;  // false: the file states none
  int body = -1;    // index in bodies
  GhostLaw law = GhostLaw::Ballistic;
};

struct World {
  int version = FORMAT_VERSION;
  std::string scene;    // the program that exported it ("test4"), or the user's name
  std::string title;
  std::string description;  // what the world shows and its analytic answer, in words
  double time = 0.0;    // simulated seconds when exported
  double duration = 0.0;  // s: the run a headless run makes without --seconds; 0: the program's default
  Settings settings;
  std::vector<Body> bodies;
  std::vector<Geom> geoms;  // in the order the program made them
  std::vector<Joint> joints;
  std::vector<Surface> surfaces;   // at least one
  int defaultSurface = 0;          // for every pair not in pairSurfaces
  std::vector<PairSurface> pairSurfaces;
  std::vector<Measure> measures;
  std::vector<Event> events;  // in time order
  Ghost ghost;
  // In memory only: what an imported file (MJCF) has that this format does
  // not carry, one line each, said before the run and in the metrics.
  std::vector<std::string> notes;

  // The surface two geoms (indices) touch with.
  const Surface& surfaceBetween(int geom1, int geom2) const;
  // Whether the category/collide bits, bodies and joints let the two geoms touch.
  bool mayTouch(int geom1, int geom2) const;
};

const char* shapeName(ShapeKind kind);
const char* jointName(JointKind kind);
const char* measureName(MeasureKind kind);
const char* ghostLawName(GhostLaw law);

}  // namespace odelab::world
