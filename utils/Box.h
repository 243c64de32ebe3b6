#pragma once

#include "AbstractObject.h"

namespace odelab {

// A box [width, height, depth] along [x, y, z] with its mass spread uniformly.
class Box : public AbstractObject {
 public:
  Box(dWorldID world, dSpaceID space, double width, double height, double depth, double mass);
  void sides(dVector3 out) const { dGeomBoxGetLengths(getGeom(), out); }
};

}  // namespace odelab
