#pragma once

// Continuous collision for fast bodies against static geometry (the remedy
// of test10 --ccd). ODE tests contacts only at the start of a step, so a
// body that moves or turns far in one step can cross a thin static geom
// unseen. Before each step, a fast body is swept along its motion in the
// step (its travel and its turn) against the static geoms:
//
// 1. Time of impact by conservative advancement: a lower bound on the
//    distance between the shapes, divided by a bound on how fast any point
//    of the moving body can approach (|travel| + |turn| x reach), is a part
//    of the step in which they cannot touch; advancing by it again and again
//    reaches the first touching pose, with rotation bounded. The distance
//    bounds are exact in sign (zero exactly when the shapes touch) for boxes
//    and spheres against boxes, planes and spheres: the separating axes of
//    two boxes, closest points otherwise. Other shapes are held by their
//    bounding boxes, and ODE's own dCollide decides where they touch.
// 2. Clamp: the body is moved along its motion (position and orientation)
//    to that pose, overlapping by at most `contactDepth`, velocities
//    unchanged, so that the coming collide finds the contact.
// 3. Speculative contacts: every corner of a moving box that its motion
//    brings to a static geom within the step gets a frictionless contact
//    that lets it close only part of the gap in the step (ODE's
//    dContactMotionN).
//    A corner-first hit turns the rest of the box toward the wall at a rate
//    no single step can integrate; these contacts stop the other corners
//    too, in the same solve.
//
// The wall stops the body through contacts in every case; no velocity is
// edited. What it cannot guarantee: see doc/tests/test10.md ("Limits").
#include <ode/ode.h>

#include <vector>

namespace odelab {

// A body's motion over one step as the sweep models it: its origin (the
// centre of mass) moves along `travel` at a constant rate while the body
// turns at a constant rate through the rotation vector `turn` (axis times
// angle in radians), so at fraction s of the step the body is at
// p + s travel, turned by s turn about its origin.
struct StepMotion {
  double travel[3] = {0, 0, 0};
  double turn[3] = {0, 0, 0};
};

// The motion ODE's next step gives a body, as the sweep models it: travel
// (v + g step) step (the step updates the velocity first), turn w step.
StepMotion nextStepMotion(dBodyID body, const double gravity[3], double step);

// When a moving geom first overlaps a fixed one along a motion.
struct Impact {
  enum Kind {
    None,             // they do not touch during the motion
    AlreadyTouching,  // they overlap at its start
    At,               // they first overlap at `fraction`, by at most the depth asked for
    Unresolved,       // the search ran out of iterations (a grazing motion)
  } kind = None;
  double fraction = 0.0;  // of the motion, in [0, 1]
};

// The first fraction of `motion` at which `moving` (a geom on `body`)
// overlaps the static geom `fixed` by at most `depth` (m): exactly for
// boxes, spheres and planes, as ODE's dCollide reports it for other shapes.
// Leaves the body where it was.
Impact timeOfImpact(dBodyID body, dGeomID moving, const StepMotion& motion, dGeomID fixed, double depth,
                    int maxIterations = 200);

// A lower bound on the distance between two geoms at their present poses,
// negative or zero when they overlap: exact in sign for boxes and spheres
// against boxes, planes and spheres (a plane must be the fixed one).
// Other shapes are taken as their bounding boxes.
double separationBound(dGeomID moving, dGeomID fixed);

enum class SweepResult {
  Slow,        // no point of the body moves far in the step: not swept
  Clear,       // swept: it touches no static geom during the step
  Touching,    // it already touches one and is not moved: the coming collide finds that contact
  Clamped,     // moved along its motion to the first touching pose
  Unresolved,  // the search ran out of iterations: left where it was
};

class SweptCollision {
 public:
  struct Options {
    // A body is swept when a point of it may move more than this fraction
    // of its smallest half-extent in the step: below its half-extent it
    // cannot reach a wall's mid-plane unseen, whatever the wall.
    double fastFraction = 0.5;
    double contactDepth = 1e-3;  // m: the deepest overlap a clamp leaves
    int maxIterations = 200;     // per static geom and step
    bool speculativeContacts = true;
    // The part of its gap a corner may close in one step. 1 would be the
    // linear prediction's exact bound, but a turning corner leaves the
    // straight line (by up to r angle^2 / 2) and QuickStep's 20 iterations
    // leave part of a 10,000 m/s stop unsolved: corner-first cubes at
    // 10,000 m/s passed 5 times in 1000 with 1, none with 0.5 (once in a
    // 16,500-launch scan), none in four scans with 0.25 (doc/tests/test10.md).
    double speculativeClosing = 0.25;
  };
  struct Counts {
    long long sweeps = 0;               // body-steps fast enough to be swept
    long long clamps = 0;               // ... moved to a first touching pose
    long long speculativeContacts = 0;  // contacts added for corners on their way in
    long long unresolved = 0;           // ... whose search ran out of iterations
  };

  SweptCollision() = default;
  explicit SweptCollision(const Options& options) : options_(options) {}

  // The static geoms to sweep against (the bounding data is taken now: they must not move).
  void setStaticGeoms(const std::vector<dGeomID>& geoms);
  // A body to sweep with the sizes its speed test needs, fixed for a rigid
  // geom: taken once (when the body is made), not every step.
  struct Body {
    dBodyID body;
    dGeomID geom;
    double smallestHalfExtent;  // m
    double reach;               // m: the farthest point of the geom from the body's origin
  };
  static Body describeBody(dBodyID body, dGeomID geom);
  // Before a step (after forces, before collision): sweeps the body and,
  // where it would touch a static geom in the step, clamps it and adds
  // speculative contacts to `contacts` (emptied by the caller after the step).
  SweepResult sweep(const Body& moving, double step, const double gravity[3], dWorldID world,
                    dJointGroupID contacts);
  SweepResult sweep(dBodyID body, dGeomID geom, double step, const double gravity[3], dWorldID world,
                    dJointGroupID contacts);

  const Counts& counts() const { return counts_; }
  void resetCounts() { counts_ = Counts{}; }

  // Quick-rejection data of a static geom.
  struct StaticGeom {
    dGeomID geom;
    bool plane;
    double lower[3], upper[3];  // bounding box (not for a plane)
    double normal[3], offset;   // plane: normal . x = offset
  };

 private:
  // Contacts for the corners of the box `geom` that move toward `fixed`
  // and can reach it in the step; how many.
  static int addSpeculativeContacts(dBodyID body, dGeomID geom, dGeomID fixed, const double velocity[3], double step,
                                    double closing, dWorldID world, dJointGroupID contacts);

  Options options_;
  std::vector<StaticGeom> statics_;
  // This sweep's statics past the quick rejection, and those the body
  // touches now (members: no allocation a step).
  std::vector<const StaticGeom*> near_, touching_;
  Counts counts_;
};

}  // namespace odelab
