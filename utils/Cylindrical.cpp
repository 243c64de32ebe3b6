#include "Cylindrical.h"

namespace odelab {

namespace {

constexpr int ALONG_Z = 3;  // ODE's direction argument: the geom's own axis

dGeomID geomOf(Shape kind, dSpaceID space, double radius, double length) {
  return kind == Shape::Capsule ? dCreateCapsule(space, radius, length) : dCreateCylinder(space, radius, length);
}

dBodyID bodyOf(Shape kind, dWorldID world, double radius, double length, double mass) {
  dBodyID body = dBodyCreate(world);
  dMass m;
  if (kind == Shape::Capsule)
    dMassSetCapsuleTotal(&m, mass, ALONG_Z, radius, length);
  else
    dMassSetCylinderTotal(&m, mass, ALONG_Z, radius, length);
  dBodySetMass(body, &m);
  return body;
}

}  // namespace

Cylindrical::Cylindrical(Shape kind, dWorldID world, dSpaceID space, double radius, double length, double mass)
    : AbstractObject(kind, geomOf(kind, space, radius, length), bodyOf(kind, world, radius, length, mass)) {}

void Cylindrical::dimensions(double& radius, double& length) const {
  dReal r, l;
  if (shape() == Shape::Capsule)
    dGeomCapsuleGetParams(getGeom(), &r, &l);
  else
    dGeomCylinderGetParams(getGeom(), &r, &l);
  radius = r;
  length = l;
}

}  // namespace odelab
