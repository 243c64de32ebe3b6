#include "Box.h"

namespace odelab {

namespace {
dBodyID boxBody(dWorldID world, double width, double height, double depth, double mass) {
  dBodyID body = dBodyCreate(world);
  dMass m;
  dMassSetBox(&m, 1.0, width, height, depth);
  dMassAdjust(&m, mass);
  dBodySetMass(body, &m);
  return body;
}
}  // namespace

Box::Box(dWorldID world, dSpaceID space, double width, double height, double depth, double mass)
    : AbstractObject(Shape::Box, dCreateBox(space, width, height, depth),
                     boxBody(world, width, height, depth, mass)) {}

}  // namespace odelab
