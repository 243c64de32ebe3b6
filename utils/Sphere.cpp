#include "Sphere.h"

namespace odelab {

namespace {
dBodyID sphereBody(dWorldID world, double radius, double mass) {
  dBodyID body = dBodyCreate(world);
  dMass m;
  dMassSetSphereTotal(&m, mass, radius);
  dBodySetMass(body, &m);
  return body;
}
}  // namespace

Sphere::Sphere(dWorldID world, dSpaceID space, double radius, double mass)
    : AbstractObject(Shape::Sphere, dCreateSphere(space, radius), sphereBody(world, radius, mass)) {}

}  // namespace odelab
