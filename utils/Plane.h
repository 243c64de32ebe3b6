#pragma once

#include "AbstractObject.h"

namespace odelab {

// A static infinite plane a*x + b*y + c*z = d; the default is the ground y = 0.
class Plane : public AbstractObject {
 public:
  explicit Plane(dSpaceID space, double a = 0, double b = 1, double c = 0, double d = 0);
  void params(dVector4 out) const { dGeomPlaneGetParams(getGeom(), out); }
};

}  // namespace odelab
