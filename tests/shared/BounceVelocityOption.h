#pragma once

// --bounce-velocity for the scenes that bounce (test1, test9): ODE's
// surface.bounce_vel, the slowest impact that still bounces. The thesis
// states it for test1 only, so each scene says where its default comes from.

#include <string>

#include "Knob.h"

namespace odelab {

inline Knob bounceVelocityKnob(double& bounceVelocity, const std::string& source) {
  return Knob::real("bounce_velocity", "bounce velocity", "m/s", bounceVelocity, 0.0, 1000.0)
      .withOption("--bounce-velocity", "slowest impact that bounces, m/s (" + source + ")");
}

}  // namespace odelab
