#pragma once

#include "AbstractObject.h"

namespace odelab {

// A solid sphere of uniform density.
class Sphere : public AbstractObject {
 public:
  Sphere(dWorldID world, dSpaceID space, double radius, double mass);
  double radius() const { return dGeomSphereGetRadius(getGeom()); }
};

}  // namespace odelab
