#pragma once

#include <ode/ode.h>

#include <cmath>
#include <random>

namespace odelab {

// Random starting turns for a launched body, drawn from the scene's seeded
// generator so that a run repeats.

// A uniformly random orientation (Shoemake's unit quaternion from three
// uniform numbers): a cube meets a wall with a corner or an edge first.
inline void turnAtRandom(dBodyID body, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double u1 = uniform(random), u2 = uniform(random), u3 = uniform(random);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1), turn = 2.0 * M_PI;
  const dQuaternion q = {a * std::sin(turn * u2), a * std::cos(turn * u2), b * std::sin(turn * u3),
                         b * std::cos(turn * u3)};
  dBodySetQuaternion(body, q);
}

// A turn at `spin` rad/s about a uniformly random axis (a normalised Gaussian vector).
inline void spinAtRandom(dBodyID body, double spin, std::mt19937& random) {
  std::normal_distribution<double> normal(0.0, 1.0);
  double axis[3] = {normal(random), normal(random), normal(random)};
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  dBodySetAngularVel(body, spin * axis[0] / n, spin * axis[1] / n, spin * axis[2] / n);
}

}  // namespace odelab
