#include "Plane.h"

namespace odelab {

Plane::Plane(dSpaceID space, double a, double b, double c, double d)
    : AbstractObject(Shape::Plane, dCreatePlane(space, a, b, c, d), nullptr) {
  color = Color{0.55f, 0.6f, 0.55f};
}

}  // namespace odelab
