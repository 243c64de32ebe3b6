#pragma once

#include <ode/ode.h>

#include <algorithm>
#include <cmath>

// Small measures of one body that several scenes report.
namespace odelab {

// Length of a 3-vector (a velocity, an offset).
inline double vectorLength(const dReal* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Speed of a body's centre of mass, m/s.
inline double speedOf(dBodyID body) { return vectorLength(dBodyGetLinearVel(body)); }

// Angle in degrees between a body's local y axis and the world's y axis:
// 0 for a body standing as built, 90 for one on its side.
inline double tiltDegrees(dBodyID body) {
  const dReal* r = dBodyGetRotation(body);  // row-major 3x4: r[5] is the y component of local y
  return std::acos(std::clamp<double>(r[5], -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace odelab
