// test10 - Maximum velocity (thesis 5.11): small cubes are launched at a thin
// vertical wall. ODE tests collisions only at the start of each step (no
// continuous collision detection), so a fast enough cube jumps over the wall
// or lands past its middle and is pushed out of the far side. The test finds
// the highest launch velocity at which every cube is still stopped.
//
// Measures: whether each launch passed through (its centre ends beyond the
// wall's far face); with --find-max-velocity, the highest velocity V such
// that every launch at every tested velocity up to V was stopped, tested every
// 1 m/s up to 1000 m/s and every 0.1% above.
//
// Geometry of the limit: a cube of half-size h crossing a wall of thickness t
// overlaps it while its centre lies within h + t/2 of the wall's mid-plane.
// At the first step that overlaps, the box-box test pushes the cube out along
// the axis of least penetration: back if its centre is still short of the
// mid-plane, forward (through) if it is past it. So every arrival is stopped
// while one step's travel v*step is below h + t/2; above that it depends on
// where the cube happens to be at the steps around the wall (the phase), which
// for a fixed launch point is a fixed function of v.
//
// The remedy (--ccd, key T; off by default, the thesis's behaviour): before
// each step every body whose next step's travel exceeds half its smallest
// half-extent is swept along that travel against the static geometry. If it
// would touch a static geom during the step, it is moved forward along its
// path to the first touching position (overlap at most 1 mm), velocity
// unchanged, so the next collide finds the contact and the solver stops it:
// the wall still stops the cube through contacts, never by a velocity edit.
// Also measured: how many times the sweep intervened (ccd_clamps) and the
// energy a stopped cube keeps (max_stop_energy_ratio). Its limit, turning
// during the step, shows with --random-orientation (cubes hit corner first).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "FormatValue.h"
#include "Plane.h"
#include "TestMain.h"

namespace {

using namespace odelab;

// The wall: thickness from the thesis; position and size (proposed).
constexpr double WALL_THICKNESS = 0.05;
constexpr double WALL_X = 0.0;       // centre of the wall (proposed)
constexpr double WALL_HEIGHT = 6.0;  // standing on the ground (proposed)
constexpr double WALL_WIDTH = 6.0;   // along z (proposed)
constexpr double WALL_NEAR_FACE = WALL_X - WALL_THICKNESS / 2;
constexpr double WALL_FAR_FACE = WALL_X + WALL_THICKNESS / 2;

// The launched cube, from the thesis.
constexpr double CUBE_SIDE = 0.4;
constexpr double CUBE_HALF = CUBE_SIDE / 2;
constexpr double CUBE_MASS = 1.0;
constexpr double LAUNCH_X = -4.0, LAUNCH_Y = 3.0, LAUNCH_Z = 0.0;

// World settings from the thesis: they limit how deep a cube may sink into the wall.
constexpr double ERP = 0.3;
constexpr double CFM = 0.0;
constexpr double SURFACE_LAYER = 0.0;

constexpr double DEFAULT_VELOCITY = 200.0;  // m/s (proposed): stopped at the default step
// F5 changes the velocity by 10 m/s below 1000 m/s and by 100 m/s from there up.
constexpr double F5_FINE_STEP = 10.0, F5_COARSE_STEP = 100.0, F5_COARSE_FROM = 1000.0;

// The scan of --find-max-velocity: every 1 m/s up to 1000 m/s, then every 0.1%.
constexpr double SCAN_FINE_STEP = 1.0;
constexpr double SCAN_FINE_LIMIT = 1000.0;
constexpr double SCAN_COARSE_RATIO = 0.001;
constexpr double DEFAULT_SCAN_LIMIT = 100000.0;  // m/s: where the scan gives up (proposed)
constexpr double DEFAULT_BAND_FACTOR = 1.5;      // keep scanning to 1.5x the first failure (proposed)

// A launch is over when the cube is wholly past the wall, or moves no longer
// toward it on the near side; failing both, after the time it needs to reach
// the wall plus this much (a soft contact, with CFM > 0, may take a while).
constexpr double SETTLE_SECONDS = 0.05;
// The window keeps launched cubes to show where they ended; farther away they go.
constexpr double KEEP_RADIUS = 100.0;

// Continuous collision for fast bodies (--ccd). A body is swept when one
// step's travel exceeds this fraction of its smallest half-extent: below its
// half-extent a body cannot reach a wall's mid-plane on the first step that
// overlaps it, whatever the wall's thickness; half of that leaves a margin
// for turning during the step (proposed).
constexpr double CCD_TRAVEL_FRACTION = 0.5;
// Along the swept path, touching is probed every half of the smallest
// half-extent (an overlap shorter than that, a grazed corner, can be missed)
// and the first touching position found to this depth (proposed).
constexpr double CCD_PROBE_FRACTION = 0.5;
constexpr double CCD_CONTACT_TOLERANCE = 1e-3;  // m

enum class Outcome { InFlight, Stopped, Passed };

const char* outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::InFlight:
      return "in flight";
    case Outcome::Stopped:
      return "stopped";
    case Outcome::Passed:
      return "passed through";
  }
  return "?";
}

// ---- Continuous collision: a swept test against static geometry ----------

double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Half-width of a geom along the unit direction n (its support): exact for
// boxes and spheres, the axis-aligned bounding box's for other shapes.
double halfWidthAlong(dGeomID geom, const double n[3]) {
  switch (dGeomGetClass(geom)) {
    case dBoxClass: {
      dVector3 sides;
      dGeomBoxGetLengths(geom, sides);
      const dReal* r = dGeomGetRotation(geom);  // 3x4 row-major; column i is the box's axis i
      double width = 0.0;
      for (int i = 0; i < 3; ++i) width += 0.5 * sides[i] * std::fabs(r[i] * n[0] + r[4 + i] * n[1] + r[8 + i] * n[2]);
      return width;
    }
    case dSphereClass:
      return dGeomSphereGetRadius(geom);
    default: {
      dReal aabb[6];
      dGeomGetAABB(geom, aabb);
      double width = 0.0;
      for (int k = 0; k < 3; ++k) width += 0.5 * (aabb[2 * k + 1] - aabb[2 * k]) * std::fabs(n[k]);
      return width;
    }
  }
}

double smallestHalfExtent(dGeomID geom) {
  switch (dGeomGetClass(geom)) {
    case dBoxClass: {
      dVector3 sides;
      dGeomBoxGetLengths(geom, sides);
      return 0.5 * std::min({sides[0], sides[1], sides[2]});
    }
    case dSphereClass:
      return dGeomSphereGetRadius(geom);
    default: {
      dReal aabb[6];
      dGeomGetAABB(geom, aabb);
      return 0.5 * std::min({aabb[1] - aabb[0], aabb[3] - aabb[2], aabb[5] - aabb[4]});
    }
  }
}

// True for two boxes whose axes are parallel (each axis of one along an
// axis of the other, to 1e-9).
bool parallelBoxes(dGeomID a, dGeomID b) {
  if (dGeomGetClass(a) != dBoxClass || dGeomGetClass(b) != dBoxClass) return false;
  const dReal* ra = dGeomGetRotation(a);
  const dReal* rb = dGeomGetRotation(b);
  for (int i = 0; i < 3; ++i) {
    double largest = 0.0, sum = 0.0;
    for (int j = 0; j < 3; ++j) {
      const double c = std::fabs(ra[i] * rb[j] + ra[4 + i] * rb[4 + j] + ra[8 + i] * rb[8 + j]);
      largest = std::max(largest, c);
      sum += c;
    }
    if (largest < 1.0 - 1e-9 || sum - largest > 1e-9) return false;
  }
  return true;
}

// The fractions s of the travel d (centre at p + s d) for which the moving
// geom may overlap; narrowed by one slab: |axis . (centre - slabCentre)| <= halfWidth.
struct Interval {
  double enter = -std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
  bool exact = false;  // the bound is the shapes' own (no probing needed)
  bool empty() const { return enter > exit; }
  void makeEmpty() { enter = 1.0, exit = 0.0; }
  void clipBySlab(const double axis[3], const double slabCentre[3], double halfWidth, const double p[3],
                  const double d[3]) {
    const double offset[3] = {p[0] - slabCentre[0], p[1] - slabCentre[1], p[2] - slabCentre[2]};
    const double start = dot3(axis, offset), rate = dot3(axis, d);
    if (std::fabs(rate) < 1e-300) {
      if (std::fabs(start) > halfWidth) makeEmpty();
      return;
    }
    double a = (-halfWidth - start) / rate, b = (halfWidth - start) / rate;
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    exit = std::min(exit, b);
  }
};

// A conservative interval: the static geom grown by the moving geom's
// half-width along each of its axes (a box's own axes, a plane's normal, or
// the world axes around a bounding box). Every real overlap lies inside it.
Interval mayOverlap(dGeomID moving, dGeomID fixed, const double p[3], const double d[3]) {
  Interval interval;
  switch (dGeomGetClass(fixed)) {
    case dBoxClass: {
      dVector3 sides;
      dGeomBoxGetLengths(fixed, sides);
      const dReal* r = dGeomGetRotation(fixed);
      const dReal* c = dGeomGetPosition(fixed);
      const double centre[3] = {c[0], c[1], c[2]};
      for (int i = 0; i < 3 && !interval.empty(); ++i) {
        const double axis[3] = {r[i], r[4 + i], r[8 + i]};
        interval.clipBySlab(axis, centre, 0.5 * sides[i] + halfWidthAlong(moving, axis), p, d);
      }
      interval.exact = parallelBoxes(moving, fixed);
      return interval;
    }
    case dPlaneClass: {
      dVector4 plane;  // n . x = plane[3], solid where n . x < plane[3]
      dGeomPlaneGetParams(fixed, plane);
      const double n[3] = {plane[0], plane[1], plane[2]};
      const double gap = dot3(n, p) - plane[3] - halfWidthAlong(moving, n), rate = dot3(n, d);
      if (rate < 0.0) {
        interval.enter = -gap / rate;
      } else if (gap > 0.0) {
        interval.makeEmpty();
      }
      // A box's or a sphere's half-width along the normal is exact.
      interval.exact = dGeomGetClass(moving) == dBoxClass || dGeomGetClass(moving) == dSphereClass;
      return interval;
    }
    default: {
      dReal aabb[6];
      dGeomGetAABB(fixed, aabb);
      for (int k = 0; k < 3 && !interval.empty(); ++k) {
        const double axis[3] = {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0};
        const double centre[3] = {0.5 * (aabb[0] + aabb[1]), 0.5 * (aabb[2] + aabb[3]), 0.5 * (aabb[4] + aabb[5])};
        interval.clipBySlab(axis, centre, 0.5 * (aabb[2 * k + 1] - aabb[2 * k]) + halfWidthAlong(moving, axis), p, d);
      }
      return interval;
    }
  }
}

bool touches(dGeomID a, dGeomID b) {
  dContactGeom contact;
  return dCollide(a, b, 1, &contact, sizeof(dContactGeom)) > 0;
}

constexpr double NO_CONTACT = std::numeric_limits<double>::infinity();

// The first fraction s in (0, 1] of the travel d at which the body's geom
// touches `fixed` (overlapping by at most CCD_CONTACT_TOLERANCE), found with
// ODE's own dCollide: probed from the conservative entry on, then bisected.
// NO_CONTACT when it does not touch during the step, or already touches now
// (then the next collide finds that contact without help). Moves the body.
double firstTouch(dBodyID body, dGeomID moving, dGeomID fixed, const double p[3], const double d[3],
                  const Interval& may, double probeSpacing) {
  const double length = std::sqrt(dot3(d, d));
  auto touchesAt = [&](double s) {
    dBodySetPosition(body, p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]);
    return touches(moving, fixed);
  };
  double clear = std::max(may.enter, 0.0);
  if (clear == 0.0 && touchesAt(0.0)) return NO_CONTACT;
  const double last = std::min(may.exit, 1.0);
  const double tolerance = CCD_CONTACT_TOLERANCE / length, spacing = probeSpacing / length;
  // First probe just past the conservative entry. Where the bound is exact
  // (two boxes with parallel axes: their Minkowski sum is the grown box)
  // this overlaps by the tolerance, so it is the touching position without
  // asking; otherwise dCollide says.
  const double firstProbe = std::min(clear + tolerance, last);
  if (may.exact && firstProbe < last) return firstProbe;
  if (touchesAt(firstProbe)) return firstProbe;
  if (firstProbe >= last) return NO_CONTACT;
  clear = firstProbe;
  for (double s = std::min(clear + spacing, last);; s = std::min(s + spacing, last)) {
    if (touchesAt(s)) {
      while (s - clear > tolerance) {
        const double mid = 0.5 * (clear + s);
        (touchesAt(mid) ? s : clear) = mid;
      }
      return s;
    }
    if (s >= last) return NO_CONTACT;
    clear = s;
  }
}

// A static geom with what the sweep's quick rejection needs, computed once:
// its bounding box, or for a plane its normal and offset.
struct StaticShape {
  dGeomID geom;
  bool plane;
  double lower[3], upper[3];  // bounding box (not for a plane)
  double normal[3], offset;   // plane: normal . x = offset
};

StaticShape describeStatic(dGeomID geom) {
  StaticShape shape{geom, dGeomGetClass(geom) == dPlaneClass, {}, {}, {}, 0.0};
  if (shape.plane) {
    dVector4 plane;
    dGeomPlaneGetParams(geom, plane);
    for (int k = 0; k < 3; ++k) shape.normal[k] = plane[k];
    shape.offset = plane[3];
    return shape;
  }
  dReal aabb[6];
  dGeomGetAABB(geom, aabb);
  for (int k = 0; k < 3; ++k) shape.lower[k] = aabb[2 * k], shape.upper[k] = aabb[2 * k + 1];
  return shape;
}

// A body to sweep, with its size measures (fixed for a rigid geom).
struct MovingShape {
  dBodyID body;
  dGeomID geom;
  double smallestHalfExtent;
  double boundingRadius;  // of a sphere round the geom's centre
};

MovingShape describeMoving(dBodyID body, dGeomID geom) {
  double radius = 0.0;
  if (dGeomGetClass(geom) == dBoxClass) {
    dVector3 sides;
    dGeomBoxGetLengths(geom, sides);
    radius = 0.5 * std::sqrt(dot3(sides, sides));
  } else if (dGeomGetClass(geom) == dSphereClass) {
    radius = dGeomSphereGetRadius(geom);
  } else {
    dReal aabb[6];
    dGeomGetAABB(geom, aabb);
    const double half[3] = {0.5 * (aabb[1] - aabb[0]), 0.5 * (aabb[3] - aabb[2]), 0.5 * (aabb[5] - aabb[4])};
    radius = std::sqrt(dot3(half, half));
  }
  return {body, geom, smallestHalfExtent(geom), radius};
}

// Quick rejection: the sphere round the body, swept from c to c + d, stays
// clear of the static geom's bounding box or plane.
bool sweptSphereMisses(const StaticShape& fixed, const double c[3], const double d[3], double radius) {
  if (fixed.plane) {
    const double start = dot3(fixed.normal, c) - fixed.offset;
    return start > radius && start + dot3(fixed.normal, d) > radius;
  }
  for (int k = 0; k < 3; ++k) {
    if (std::min(c[k], c[k] + d[k]) - radius > fixed.upper[k]) return true;
    if (std::max(c[k], c[k] + d[k]) + radius < fixed.lower[k]) return true;
  }
  return false;
}

enum class Sweep { Slow, Clear, Clamped };

// Before a step: if the body's travel in that step, (v + g step) step, is
// long for its size, sweeps it against every static geom; if it would touch
// one, moves it along its path to the first touching position (velocity
// unchanged) so that the coming collide finds the contact. Cheap unless the
// body is fast AND near a static geom: a speed test, then a bounding test.
Sweep sweepBody(const MovingShape& moving, const std::vector<StaticShape>& statics, const double gravity[3],
                double step) {
  const dReal* v = dBodyGetLinearVel(moving.body);
  const double d[3] = {(v[0] + gravity[0] * step) * step, (v[1] + gravity[1] * step) * step,
                       (v[2] + gravity[2] * step) * step};
  const double slowTravel = CCD_TRAVEL_FRACTION * moving.smallestHalfExtent;
  if (dot3(d, d) <= slowTravel * slowTravel) return Sweep::Slow;
  const dReal* centre = dGeomGetPosition(moving.geom);
  const double c[3] = {centre[0], centre[1], centre[2]};
  const dReal* position = dBodyGetPosition(moving.body);
  const double p[3] = {position[0], position[1], position[2]};
  double first = NO_CONTACT;
  bool probed = false;
  for (const StaticShape& fixed : statics) {
    if (sweptSphereMisses(fixed, c, d, moving.boundingRadius)) continue;
    const Interval may = mayOverlap(moving.geom, fixed.geom, c, d);
    if (may.empty() || may.enter > 1.0 || may.exit < 0.0) continue;
    probed = true;
    first = std::min(first, firstTouch(moving.body, moving.geom, fixed.geom, p, d, may,
                                       CCD_PROBE_FRACTION * moving.smallestHalfExtent));
  }
  if (!probed) return Sweep::Clear;
  const double s = first == NO_CONTACT ? 0.0 : first;
  dBodySetPosition(moving.body, p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]);
  return first == NO_CONTACT ? Sweep::Clear : Sweep::Clamped;
}

// Kinetic (linear and rotational) plus potential energy of a body, J.
double mechanicalEnergy(dBodyID body, dWorldID world) {
  dMass mass;
  dBodyGetMass(body, &mass);
  const dReal* v = dBodyGetLinearVel(body);
  const dReal* w = dBodyGetAngularVel(body);
  dVector3 wb;  // angular velocity in body axes, where the inertia is given
  dBodyVectorFromWorld(body, w[0], w[1], w[2], wb);
  double rotational = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotational += wb[i] * mass.I[i * 4 + j] * wb[j];
  dVector3 gravity;
  dWorldGetGravity(world, gravity);
  const dReal* p = dBodyGetPosition(body);
  return 0.5 * mass.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * rotational -
         mass.mass * (gravity[0] * p[0] + gravity[1] * p[1] + gravity[2] * p[2]);
}

struct Launch {
  Box* cube;
  MovingShape shape;  // for the sweep
  double velocity;
  double launchedAt;
  double launchEnergy;  // J, with the ground (y = 0) as zero of height
  Outcome outcome = Outcome::InFlight;
};

class MaximumVelocity : public AbstractWindow {
 public:
  MaximumVelocity() : AbstractWindow("test10 - Maximum velocity", settingsForThisScene()) {
    bindKey(SDLK_b, "B", "launch a cube from [-4, 3, 0] toward the wall at the launch velocity",
            [this](int) { launch(velocity_); });
    bindKey(SDLK_F5, "F5", "launch velocity up (Shift: down): by 10 m/s below 1000 m/s, by 100 m/s from 1000 m/s",
            [this](int direction) { changeVelocity(direction); });
    // T (tunnelling): C is the shared key for the contact markers.
    bindKey(SDLK_t, "T",
            "continuous collision for fast bodies on / off (--ccd): sweep each fast body's step against "
            "the static geometry",
            [this](int) { toggleCcd(); });
    keepAcrossRewind(velocity_);
    keepAcrossRewind(ccd_);
  }

  void addOptions(CLI::App& app) override {
    app.add_option("--velocity", velocity_, "launch velocity in m/s (window: the starting F5 value)")
        ->check(cli::positive(1e7))
        ->capture_default_str();
    launchesOption_ = app.add_option("--launches", launches_,
                                     "headless: cubes launched one at a time (the previous one removed) at "
                                     "--velocity; with --find-max-velocity, launches per tested velocity "
                                     "(default 5, or 1 when scanning)")
                          ->check(CLI::Range(1, 100000));
    app.add_flag("--find-max-velocity", findMaxVelocity_,
                 "headless: scan launch velocities from 1 m/s, every 1 m/s up to 1000 m/s and every 0.1% above, "
                 "for the highest velocity at which every launch so far was stopped");
    scanOptions_.push_back(
        app.add_option("--scan-limit", scanLimit_, "--find-max-velocity gives up above this velocity (m/s)")
            ->check(cli::positive(1e7))
            ->capture_default_str());
    scanOptions_.push_back(
        app.add_option("--band-factor", bandFactor_,
                       "--find-max-velocity keeps scanning up to this multiple of the first failing velocity, to "
                       "show whether stops reappear above it")
            ->check(cli::finiteRange(1.0, 100.0))
            ->capture_default_str());
    app.add_flag("--phase-jitter", phaseJitter_,
                 "start each launch up to one step's travel behind [-4, 3, 0] (uniform, from --seed), so the "
                 "cube meets the wall at a random phase of the step; off: the thesis's fixed launch point");
    app.add_flag("--random-orientation", randomOrientation_,
                 "launch each cube turned to a uniformly random orientation (from --seed), so it meets the wall "
                 "with a corner or an edge first; off: unturned, face on (the thesis's)");
    app.add_flag("--ccd", ccd_,
                 "continuous collision for fast bodies: before each step, a body whose travel in the step exceeds "
                 "half its smallest half-extent is swept against the static geometry and, if it would touch it, "
                 "moved along its path to the first touching position, so the contact stops it (window: T); off: "
                 "the thesis's behaviour");
  }

  void checkOptions() const override {
    for (const CLI::Option* option : scanOptions_)
      if (option->count() && !findMaxVelocity_)
        throw UsageError(option->get_name() + ": only used with --find-max-velocity");
  }

 protected:
  void configureWorld() override { dWorldSetContactSurfaceLayer(world(), SURFACE_LAYER); }

  void buildScene() override {
    add<Plane>(space());
    Box& wall = add<Box>(world(), space(), WALL_THICKNESS, WALL_HEIGHT, WALL_WIDTH, 1.0);
    wall.setAsFixedGeom();
    wall.setPosition(WALL_X, WALL_HEIGHT / 2, 0.0);
    wall.color = Color{0.45f, 0.55f, 0.7f};
    staticShapes_.clear();
    for (const auto& object : objects())
      if (object->isFixed()) staticShapes_.push_back(describeStatic(object->getGeom()));
    launchesInScene_.clear();
    launched_ = stopped_ = passed_ = 0;
    ccdSweeps_ = ccdClamps_ = 0;
    maxStopEnergyRatio_ = 0.0;
    if (findMaxVelocity_ && !options().headless)
      notify("--find-max-velocity runs only with --headless; B launches here");
  }

  void afterStep() override {
    for (Launch& l : launchesInScene_) {
      if (l.outcome != Outcome::InFlight) continue;
      l.outcome = classify(l);
      if (l.outcome == Outcome::InFlight) continue;
      (l.outcome == Outcome::Passed ? passed_ : stopped_) += 1;
      if (l.outcome == Outcome::Stopped)
        maxStopEnergyRatio_ =
            std::max(maxStopEnergyRatio_, mechanicalEnergy(l.cube->getBody(), world()) / l.launchEnergy);
      l.cube->color = l.outcome == Outcome::Passed ? Color{0.9f, 0.25f, 0.2f} : Color{0.3f, 0.8f, 0.35f};
      lastOutcome_ = l.outcome;
      lastVelocity_ = l.velocity;
    }
    removeFarCubes();
    // afterStep runs between this step and the next collide: sweeping here is
    // sweeping before the next step.
    sweepFastBodies();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    lines.push_back("launch velocity " + formatValue(velocity_) + " m/s   B launches a cube, F5 / Shift+F5 change it");
    std::string counts = "launched " + std::to_string(launched_) + ": stopped " + std::to_string(stopped_) +
                         ", passed through " + std::to_string(passed_);
    if (lastOutcome_ != Outcome::InFlight)
      counts += "   (last: " + std::string(outcomeName(lastOutcome_)) + " at " + formatValue(lastVelocity_) + " m/s)";
    lines.push_back(counts);
    lines.push_back("every arrival is stopped below (h + t/2)/step = " + formatValue(guaranteedStopVelocity()) +
                    " m/s; (h + t)/step = " + formatValue(geometricPrediction()) + " m/s");
    lines.push_back(std::string("continuous collision (T): ") +
                    (ccd_ ? "on, " + std::to_string(ccdClamps_) + " clamps" : std::string("off")));
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = double(passed_);
    return true;
  }
  std::string plotLabel() const override { return "launches that passed the wall (of all launched)"; }

  void addMetrics(Metrics& m) const override {
    m.set("launch_velocity", findMaxVelocity_ ? 0.0 : velocity_);
    m.set("launches", launched_);
    m.set("stopped", stopped_);
    m.set("passed_through", passed_);
    m.set("geometric_prediction", geometricPrediction());
    m.set("guaranteed_stop_velocity", guaranteedStopVelocity());
    m.set("ccd", ccd_ ? 1 : 0);
    m.set("ccd_sweeps", static_cast<double>(ccdSweeps_));
    m.set("ccd_clamps", static_cast<double>(ccdClamps_));
    m.set("max_stop_energy_ratio", maxStopEnergyRatio_);
    if (!findMaxVelocity_) return;
    m.set("max_velocity", scan_.maxVelocity);
    m.set("max_velocity_resolution", scan_.maxVelocityResolution);
    m.set("first_failure_velocity", scan_.firstFailure);
    m.set("band_upper_velocity", scan_.bandUpper);
    m.set("velocities_stopped_in_band", scan_.stoppedInBand);
    m.set("velocities_passed_in_band", scan_.passedInBand);
    m.set("highest_stopped_velocity_in_band", scan_.highestStoppedInBand);
    m.set("tested_velocities", scan_.tested);
  }

  void onSettingChanged(const std::string&) override {
    // The surface layer is not part of WorldSettings; keep it at the thesis's value.
    dWorldSetContactSurfaceLayer(world(), SURFACE_LAYER);
  }

  void initialCamera(Camera& camera) const override { camera.lookAt({-7.5, 4.5, 8.5}, {-1.5, 2.2, 0.0}); }
  SceneBounds bounds() const override { return {{-1.5, 2.5, 0.0}, 6.0}; }

  int runHeadless() override {
    if (findMaxVelocity_) {
      findMaxVelocity();
    } else {
      for (int i = 0; i < launchCount(5); ++i)
        if (launchAndResolve(velocity_) == Outcome::InFlight) break;  // blew up
    }
    return reportHeadless();
  }

 private:
  static WorldSettings settingsForThisScene() {
    WorldSettings s;
    s.erp = ERP;
    s.cfm = CFM;
    return s;
  }

  double geometricPrediction() const { return (CUBE_HALF + WALL_THICKNESS) / settings().step; }
  double guaranteedStopVelocity() const { return (CUBE_HALF + WALL_THICKNESS / 2) / settings().step; }

  int launchCount(int fallback) const { return launchesOption_ && launchesOption_->count() ? launches_ : fallback; }

  void changeVelocity(int direction) {
    const bool coarse = direction > 0 ? velocity_ >= F5_COARSE_FROM : velocity_ > F5_COARSE_FROM;
    velocity_ = std::max(F5_FINE_STEP, velocity_ + direction * (coarse ? F5_COARSE_STEP : F5_FINE_STEP));
    notify("launch velocity " + formatValue(velocity_) + " m/s");
  }

  void toggleCcd() {
    ccd_ = !ccd_;
    notify(std::string("continuous collision for fast bodies ") + (ccd_ ? "on" : "off"));
    sweepFastBodies();  // the next step is already due
  }

  // Sweeps every cube (the scene's only bodies) before the coming step.
  void sweepFastBodies() {
    if (!ccd_) return;
    for (const Launch& l : launchesInScene_) sweepFastBody(l);
  }

  void sweepFastBody(const Launch& l) {
    if (!ccd_) return;
    dVector3 gravity;
    dWorldGetGravity(world(), gravity);
    const double g[3] = {gravity[0], gravity[1], gravity[2]};
    const Sweep sweep = sweepBody(l.shape, staticShapes_, g, settings().step);
    if (sweep != Sweep::Slow) ++ccdSweeps_;
    if (sweep == Sweep::Clamped) ++ccdClamps_;
  }

  Launch& launch(double velocity) {
    Box& cube = add<Box>(world(), space(), CUBE_SIDE, CUBE_SIDE, CUBE_SIDE, CUBE_MASS);
    double startX = LAUNCH_X;
    if (phaseJitter_) startX -= std::uniform_real_distribution<double>(0.0, 1.0)(random()) * velocity * settings().step;
    cube.setPosition(startX, LAUNCH_Y, LAUNCH_Z);
    cube.setLinearVelocity(velocity, 0.0, 0.0);
    if (randomOrientation_) turnAtRandom(cube);
    cube.color = Color{0.95f, 0.8f, 0.2f};
    ++launched_;
    launchesInScene_.push_back({&cube, describeMoving(cube.getBody(), cube.getGeom()), velocity, simulatedTime(),
                                mechanicalEnergy(cube.getBody(), world())});
    // Launched between steps: the framework has no before-step hook, so its
    // first step is swept here.
    sweepFastBody(launchesInScene_.back());
    return launchesInScene_.back();
  }

  // A uniformly random orientation (Shoemake's unit quaternion from three
  // uniform numbers): the cube meets the wall with a corner or an edge first.
  void turnAtRandom(Box& cube) {
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double u1 = uniform(random()), u2 = uniform(random()), u3 = uniform(random());
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1), turn = 2.0 * M_PI;
    const dQuaternion q = {a * std::sin(turn * u2), a * std::cos(turn * u2), b * std::sin(turn * u3),
                           b * std::cos(turn * u3)};
    dBodySetQuaternion(cube.getBody(), q);
  }

  // Passed: the whole cube is beyond the far face. Stopped: on the near side
  // of the mid-plane and no longer moving toward the wall (bounced back, or
  // fell to the ground short of it). Otherwise still in flight until the
  // time it needs to reach the wall plus SETTLE_SECONDS; then its centre decides.
  Outcome classify(const Launch& l) const {
    const double x = l.cube->getPosition()[0];
    const double vx = dBodyGetLinearVel(l.cube->getBody())[0];
    if (x - CUBE_HALF > WALL_FAR_FACE) return Outcome::Passed;
    if (vx <= 0.0 && x < WALL_X) return Outcome::Stopped;
    const double reachSeconds = (WALL_FAR_FACE + CUBE_HALF - LAUNCH_X) / l.velocity;
    if (simulatedTime() - l.launchedAt > reachSeconds + SETTLE_SECONDS)
      return x > WALL_FAR_FACE ? Outcome::Passed : Outcome::Stopped;
    return Outcome::InFlight;
  }

  void removeFarCubes() {
    removeIf([this](const AbstractObject& object) {
      for (auto it = launchesInScene_.begin(); it != launchesInScene_.end(); ++it) {
        if (it->cube != &object || it->outcome == Outcome::InFlight) continue;
        const dReal* p = object.getPosition();
        if (std::fabs(p[0]) < KEEP_RADIUS && p[1] > -KEEP_RADIUS) return false;
        launchesInScene_.erase(it);
        return true;
      }
      return false;
    });
  }

  // Headless: one launch on its own (the previous cube removed), stepped until
  // its outcome is known. InFlight means the simulation blew up.
  Outcome launchAndResolve(double velocity) {
    removeIf([this](const AbstractObject& object) {
      for (const Launch& l : launchesInScene_)
        if (l.cube == &object) return true;
      return false;
    });
    launchesInScene_.clear();
    launch(velocity);
    while (launchesInScene_.back().outcome == Outcome::InFlight)
      if (!runFor(settings().step)) return Outcome::InFlight;
    return launchesInScene_.back().outcome;
  }

  // True when every launch at this velocity was stopped; false when one passed
  // or the simulation blew up (then `blewUp` is set).
  bool everyLaunchStopped(double velocity, bool& blewUp) {
    bool all = true;
    for (int i = 0; i < launchCount(1); ++i) {
      const Outcome outcome = launchAndResolve(velocity);
      if (outcome == Outcome::InFlight) {
        blewUp = true;
        return false;
      }
      all = all && outcome == Outcome::Stopped;
    }
    return all;
  }

  static double nextScanVelocity(double velocity) {
    return velocity < SCAN_FINE_LIMIT ? velocity + SCAN_FINE_STEP : velocity * (1.0 + SCAN_COARSE_RATIO);
  }
  static double resolutionAt(double velocity) {
    return velocity < SCAN_FINE_LIMIT ? SCAN_FINE_STEP : velocity * SCAN_COARSE_RATIO;
  }

  // Scans upward; max_velocity is the last velocity before the first one with
  // a passing launch. After the first failure it keeps going to
  // band-factor x that velocity, counting the velocities that stop again.
  void findMaxVelocity() {
    bool blewUp = false;
    for (double v = SCAN_FINE_STEP; v <= scanLimit_ * (1 + 1e-12) && !blewUp; v = nextScanVelocity(v)) {
      if (scan_.firstFailure > 0.0 && v > scan_.bandUpper) break;
      const bool stopped = everyLaunchStopped(v, blewUp);
      if (blewUp) break;
      ++scan_.tested;
      if (scan_.firstFailure == 0.0) {
        if (stopped) {
          scan_.maxVelocity = v;
          continue;
        }
        scan_.firstFailure = v;
        scan_.bandUpper = std::min(scanLimit_, v * bandFactor_);
        continue;
      }
      if (stopped) {
        ++scan_.stoppedInBand;
        scan_.highestStoppedInBand = v;
      } else {
        ++scan_.passedInBand;
      }
    }
    scan_.maxVelocityResolution = resolutionAt(scan_.maxVelocity);
    printScanSummary(blewUp);
  }

  void printScanSummary(bool blewUp) const {
    std::cout << "scan: every 1 m/s up to 1000 m/s, every 0.1% above; " << launchCount(1) << " launch(es) per velocity"
              << (phaseJitter_ ? ", random phase" : ", fixed launch point")
              << (randomOrientation_ ? ", random orientation" : "") << (ccd_ ? ", continuous collision on" : "")
              << '\n';
    if (blewUp) std::cout << "scan: stopped early, the simulation blew up\n";
    if (scan_.firstFailure == 0.0) {
      std::cout << "scan: no launch passed up to the scan limit " << formatValue(scanLimit_) << " m/s\n";
      return;
    }
    std::cout << "max velocity " << formatValue(scan_.maxVelocity) << " m/s (resolution "
              << formatValue(scan_.maxVelocityResolution) << " m/s): every launch up to it was stopped; first launch "
              << "through at " << formatValue(scan_.firstFailure) << " m/s\n";
    std::cout << "band " << formatValue(scan_.firstFailure) << " - " << formatValue(scan_.bandUpper)
              << " m/s: " << scan_.stoppedInBand << " tested velocities stopped again, " << scan_.passedInBand
              << " passed"
              << (scan_.stoppedInBand ? " (highest stopped " + formatValue(scan_.highestStoppedInBand) + " m/s)" : "")
              << '\n';
  }

  struct ScanResult {
    double maxVelocity = 0.0;
    double maxVelocityResolution = 0.0;
    double firstFailure = 0.0;  // 0: none found up to the scan limit
    double bandUpper = 0.0;
    int stoppedInBand = 0;
    int passedInBand = 0;
    double highestStoppedInBand = 0.0;
    int tested = 0;
  };

  double velocity_ = DEFAULT_VELOCITY;
  int launches_ = 1;
  CLI::Option* launchesOption_ = nullptr;
  std::vector<const CLI::Option*> scanOptions_;
  bool findMaxVelocity_ = false;
  double scanLimit_ = DEFAULT_SCAN_LIMIT;
  double bandFactor_ = DEFAULT_BAND_FACTOR;
  bool phaseJitter_ = false;
  bool randomOrientation_ = false;
  bool ccd_ = false;

  std::vector<Launch> launchesInScene_;
  int launched_ = 0, stopped_ = 0, passed_ = 0;
  std::vector<StaticShape> staticShapes_;  // the wall and the ground, for the sweep
  long long ccdSweeps_ = 0, ccdClamps_ = 0;
  double maxStopEnergyRatio_ = 0.0;
  Outcome lastOutcome_ = Outcome::InFlight;
  double lastVelocity_ = 0.0;
  ScanResult scan_;
};

}  // namespace

int main(int argc, char** argv) {
  return odelab::runTest<MaximumVelocity>(
      argc, argv, "Cubes launched at a thin wall: the highest velocity at which the wall still stops every one.");
}
