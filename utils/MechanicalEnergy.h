#pragma once

#include <ode/ode.h>

namespace odelab {

// Kinetic (linear and rotational) plus potential energy of a body, J, with
// the potential's zero at the world origin's height along gravity.
inline double mechanicalEnergy(dBodyID body, dWorldID world) {
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

}  // namespace odelab
