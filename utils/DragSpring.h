#pragma once

#include <ode/ode.h>

#include <memory>
#include <vector>

#include "AbstractObject.h"

namespace odelab {

// What a ray from the camera hits first among the movable objects.
struct PickHit {
  int objectIndex = -1;  // -1: nothing
  double point[3] = {0, 0, 0};
  double distance = 0.0;
};

PickHit pickObject(const std::vector<std::unique_ptr<AbstractObject>>& objects, const double origin[3],
                   const double direction[3], double maxDistance = 1000.0);

// The mouse-drag spring: pulls the grabbed point of a body toward a target.
// Stiffness and damping scale with the body's mass (a critically damped
// 2 Hz oscillator whatever the mass), and the force is capped at 50 times the
// body's weight, so a drag moves a 5 kg cube and a 5000 kg cube alike
// without launching either.
class DragSpring {
 public:
  static constexpr double FREQUENCY_HZ = 2.0;
  static constexpr double MAX_FORCE_IN_WEIGHTS = 50.0;

  // Applies the spring force for one step; wakes the body if it was disabled.
  // `force` and `point` receive the force applied and the world point where
  // it acts (for the drag's energy books, DragEnergy).
  static void apply(dBodyID body, const double grabLocal[3], const double target[3], double gravity,
                    double force[3], double point[3]);
  // The grabbed point in the world frame.
  static void grabbedPoint(dBodyID body, const double grabLocal[3], double point[3]);
  // Distance from the grabbed point to the target.
  static double distance(dBodyID body, const double grabLocal[3], const double target[3]);
};

}  // namespace odelab
