#pragma once

#include <ode/ode.h>

#include <algorithm>
#include <string>
#include <vector>

#include "Box.h"
#include "FormatValue.h"
#include "SweptCollision.h"
#include "shared/LaunchOutcome.h"
#include "MechanicalEnergy.h"

namespace odelab {

// test10's bookkeeping of launched cubes: each launch's record until its
// outcome (shared/LaunchOutcome.h) is known, how many were stopped or passed
// through, the last outcome, and the most energy a stopped cube kept.

inline const char* outcomeName(scene::test10::Outcome outcome) {
  switch (outcome) {
    case scene::test10::Outcome::InFlight:
      return "in flight";
    case scene::test10::Outcome::Stopped:
      return "stopped";
    case scene::test10::Outcome::Passed:
      return "passed through";
  }
  return "?";
}

// In a window a passed cube would fly out of sight at hundreds of m/s: it
// is held where it was seen to pass, just beyond the wall, and no longer
// collides, so it changes no later launch. (Headless runs leave it be:
// nothing is drawn there.)
inline void keepInView(Box& cube) {
  const dBodyID body = cube.getBody();
  dBodySetLinearVel(body, 0, 0, 0);
  dBodySetAngularVel(body, 0, 0, 0);
  dBodySetKinematic(body);
  dGeomDisable(cube.getGeom());
}

struct Launch {
  Box* cube;
  SweptCollision::Body sweptBody;  // the cube's sizes, for the sweep
  double velocity;
  double launchedAt;
  double launchEnergy;  // J, with the ground (y = 0) as zero of height
  scene::test10::Outcome outcome = scene::test10::Outcome::InFlight;
};

class LaunchTally {
 public:
  using Outcome = scene::test10::Outcome;

  // A rebuilt scene: no launches; the last outcome stays on the HUD.
  void clear() {
    inScene.clear();
    launched = stopped = passed = 0;
    maxStopEnergyRatio = 0.0;
  }
  void add(const Launch& launch) {
    ++launched;
    inScene.push_back(launch);
  }
  int decided() const { return stopped + passed; }

  // After a step at simulated time `now`: decides the launches still in
  // flight, and hands each newly decided one to `onDecided`.
  template <class OnDecided>
  void classify(double now, dWorldID world, OnDecided onDecided) {
    for (Launch& l : inScene) {
      if (l.outcome != Outcome::InFlight) continue;
      l.outcome = scene::test10::launchOutcome(l.cube->getPosition()[0], dBodyGetLinearVel(l.cube->getBody())[0],
                                               l.velocity, now - l.launchedAt);
      if (l.outcome == Outcome::InFlight) continue;
      (l.outcome == Outcome::Passed ? passed : stopped) += 1;
      if (l.outcome == Outcome::Stopped)
        maxStopEnergyRatio = std::max(maxStopEnergyRatio, mechanicalEnergy(l.cube->getBody(), world) / l.launchEnergy);
      onDecided(l);
      lastOutcome = l.outcome;
      lastVelocity = l.velocity;
    }
  }

  // "launched 3: stopped 2, passed through 1   (last: stopped at 200 m/s)"
  std::string countsText() const {
    std::string counts = "launched " + std::to_string(launched) + ": stopped " + std::to_string(stopped) +
                         ", passed through " + std::to_string(passed);
    if (lastOutcome != Outcome::InFlight)
      counts += "   (last: " + std::string(outcomeName(lastOutcome)) + " at " + formatValue(lastVelocity) + " m/s)";
    return counts;
  }

  std::vector<Launch> inScene;  // launches whose cube is still in the scene
  int launched = 0, stopped = 0, passed = 0;
  double maxStopEnergyRatio = 0.0;
  Outcome lastOutcome = Outcome::InFlight;
  double lastVelocity = 0.0;
};

}  // namespace odelab
