#pragma once

// The measurements a world file asks for (its "measures", doc/worlds.md),
// taken from the bodies' states after every step. On another engine the link
// writes that engine's states into the ODE bodies first, so one piece of code
// measures every engine. Each measure gives metrics and a HUD line.

#include <ode/ode.h>

#include <limits>
#include <string>
#include <vector>

#include "Metrics.h"
#include "WorldDescription.h"

namespace odelab::world {

// What the bodies hold together: energy, momentum, and the centre the angular
// momentum is taken about.
struct Totals {
  double energy = 0.0;  // J: kinetic (linear and rotational) + potential, zero at the origin
  Vec3 linear{0, 0, 0};   // kg m/s
  Vec3 angular{0, 0, 0};  // kg m^2/s, about `centre`
  double linearScale = 0.0;   // sum of m |v|
  double angularScale = 0.0;  // sum of |r - centre| m |v| + |I w|
};

class WorldMeasures {
 public:
  // `bodies[i]` is the ODE body of the world's body i, or null while it is
  // out of the world (dropped in later). Call at t = 0, after building.
  WorldMeasures(const World& world, dWorldID odeWorld, dSpaceID space, std::vector<dBodyID> bodies);

  // An event changes the world from outside: what it brings (a body dropped
  // in, an impulse) joins the references energy and momentum are held to.
  void beforeEvent();
  void afterEvent(int body, dBodyID added, double time);

  void afterStep(double time);
  void addMetrics(Metrics& m) const;
  void addHudLines(std::vector<std::string>& lines) const;
  // The live plot's curve: the total energy when it is measured (false: none).
  bool plotValue(double& value) const;

 private:
  // A joint's anchor and axis as each of its bodies carries them (body frame,
  // or the world's for the static side), taken as built.
  struct JointWatch {
    dBodyID body1, body2;
    dVector3 anchor1, anchor2;
    bool hasAxis;
    dVector3 axis1, axis2;
    bool keepsTurn;  // fixed, slider: the bodies may not turn against each other
    dQuaternion relative;
  };
  // A coordinate's crossings of a value, interpolated between steps: a swing's period.
  struct Crossings {
    double previousValue = 0.0, previousTime = 0.0, first = 0.0, last = 0.0;
    int count = 0;
    bool started = false;
    double period() const;
  };
  // A probe's figure so far, and its last reading (to interpolate a time
  // between two steps).
  struct Probe {
    double figure = std::numeric_limits<double>::quiet_NaN();
    double previous = std::numeric_limits<double>::quiet_NaN(), previousTime = 0.0;
    void take(const Measure& m, double reading, double time);
  };
  double reading(const Measure& m, dBodyID body) const;
  Totals totals() const;
  double deepestContact();
  void watchJoints();
  void jointErrors();
  void tunnelling();

  const World& world_;
  dWorldID odeWorld_;
  dSpaceID space_;
  std::vector<dBodyID> bodies_;
  std::vector<double> appeared_;  // per body: when it entered the world
  std::vector<Vec3> startPosition_, startVelocity_;
  Vec3 centre_{0, 0, 0};
  Totals start_, last_, beforeEvent_;
  double energyMin_, energyMax_, energyDeviation_ = 0.0, linearDrift_ = 0.0, angularDrift_ = 0.0;
  double energyScale_ = 1.0, linearScale_ = 1.0, angularScale_ = 1.0;
  std::vector<JointWatch> joints_;
  double jointError_ = 0.0, axisError_ = 0.0, penetration_ = 0.0;
  std::vector<double> side_;  // per body: its signed distance to the tunnelling wall, NaN outside it
  std::vector<bool> tunnelled_;
  int crossings_ = 0;
  std::vector<double> ballisticError_;  // per measure
  std::vector<Crossings> swings_;       // per measure
  std::vector<Probe> probes_;           // per measure
  double restingSince_, timeToRest_;
  double time_ = 0.0;
};

}  // namespace odelab::world
