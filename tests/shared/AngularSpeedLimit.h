#pragma once

#include <ode/ode.h>

#include <string>

#include "FormatValue.h"

namespace odelab {

// The limit test6 and test7 put on every body's angular speed
// (dWorldSetMaxAngularSpeed: --max-angular-speed, and test7's F5), in
// rad/s; 0 means none.
struct AngularSpeedLimit {
  double radPerSecond = 0.0;

  bool on() const { return radPerSecond > 0; }
  // Before the bodies exist: each body copies the world's limit when it is created.
  void applyToWorld(dWorldID world) const {
    if (on()) dWorldSetMaxAngularSpeed(world, radPerSecond);
  }
  // To a body that exists already (the limit changed while running).
  void applyToBody(dBodyID body) const { dBodySetMaxAngularSpeed(body, on() ? radPerSecond : dInfinity); }
  // "10 rad/s" or "off", for the HUD and notices.
  std::string describe() const { return on() ? formatValue(radPerSecond, 4) + " rad/s" : "off"; }
};

}  // namespace odelab
