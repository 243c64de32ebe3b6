#pragma once

#include "AbstractObject.h"

namespace odelab {

// A solid of uniform density along its local z: a cylinder, or a capsule (a
// cylinder with hemispherical ends). `length` is the cylinder's, ends excluded.
class Cylindrical : public AbstractObject {
 public:
  // kind: Shape::Capsule or Shape::Cylinder.
  Cylindrical(Shape kind, dWorldID world, dSpaceID space, double radius, double length, double mass);
  void dimensions(double& radius, double& length) const;
};

}  // namespace odelab
