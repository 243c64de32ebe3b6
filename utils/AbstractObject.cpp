#include "AbstractObject.h"

namespace odelab {

AbstractObject::AbstractObject(Shape shape, dGeomID geom, dBodyID body)
    : shape_(shape), geom_(geom), ownBody_(body) {
  if (body) dGeomSetBody(geom, body);
  ++bodyChanges_;
}

AbstractObject::~AbstractObject() {
  dGeomDestroy(geom_);
  if (ownBody_) dBodyDestroy(ownBody_);
  ++bodyChanges_;
}

bool AbstractObject::isEnabled() const {
  const dBodyID body = getBody();
  return body == nullptr || dBodyIsEnabled(body);
}

void AbstractObject::setAsFixedGeom() {
  dGeomSetBody(geom_, nullptr);
  if (ownBody_) dBodyDestroy(ownBody_);
  ownBody_ = nullptr;
  ++bodyChanges_;
}

namespace {

// A geom's world pose, whether it sits on a body (with or without offset) or not.
struct Pose {
  dVector3 position;
  dMatrix3 rotation;
};

Pose poseOf(dGeomID geom) {
  Pose pose;
  dGeomCopyPosition(geom, pose.position);
  dGeomCopyRotation(geom, pose.rotation);
  return pose;
}

// Mass of `body` expressed in world coordinates (rotated, then translated).
dMass worldMassOf(dBodyID body) {
  dMass mass;
  dBodyGetMass(body, &mass);
  dMassRotate(&mass, dBodyGetRotation(body));
  const dReal* p = dBodyGetPosition(body);
  dMassTranslate(&mass, p[0], p[1], p[2]);
  return mass;
}

// Collect the world poses of every geom on `body` before the body moves.
std::vector<std::pair<dGeomID, Pose>> geomPosesOn(dBodyID body) {
  std::vector<std::pair<dGeomID, Pose>> poses;
  for (dGeomID g = dBodyGetFirstGeom(body); g; g = dBodyGetNextGeom(g)) poses.emplace_back(g, poseOf(g));
  return poses;
}

// Set `geom`'s offset on `body` so that it keeps the given world pose.
void seatAt(dGeomID geom, dBodyID body, const Pose& world) {
  const dReal* c = dBodyGetPosition(body);
  const dReal* R = dBodyGetRotation(body);
  // offset position = R^T (p - c); offset rotation = R^T Rg (ODE's 3x4 row-major layout).
  const dVector3 d{world.position[0] - c[0], world.position[1] - c[1], world.position[2] - c[2], 0};
  dVector3 local;
  dMultiply1_331(local, R, d);
  dMatrix3 localRotation;
  dMultiply1_333(localRotation, R, world.rotation);
  if (dGeomGetBody(geom) != body) dGeomSetBody(geom, body);
  dGeomSetOffsetPosition(geom, local[0], local[1], local[2]);
  dGeomSetOffsetRotation(geom, localRotation);
}

}  // namespace

bool AbstractObject::attach(AbstractObject& other) {
  const dBodyID body = getBody();
  const dBodyID otherBody = other.getBody();
  if (!body || !otherBody || body == otherBody) return false;

  dMass composite = worldMassOf(otherBody);
  const dMass component = worldMassOf(body);
  dMassAdd(&composite, &component);
  if (!dMassCheck(&composite)) return false;

  // Geoms already on the composite body, and this one, keep their world poses.
  auto poses = geomPosesOn(otherBody);
  poses.emplace_back(geom_, poseOf(geom_));

  // ODE wants the centre of mass at the body's origin. The thesis translated
  // the mass to its centre but left the body where it was, which moves the
  // centre of mass; here the body itself is moved to the summed centre.
  // Velocities of a freshly built composite are taken from `other`.
  const dVector3 centre{composite.c[0], composite.c[1], composite.c[2], 0};
  dMassTranslate(&composite, -centre[0], -centre[1], -centre[2]);
  // The summed inertia is about world axes; the body keeps other's rotation,
  // so express it in the body frame: I_body = R^T I_world R.
  const dReal* R = dBodyGetRotation(otherBody);
  dMatrix3 Rt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Rt[i * 4 + j] = R[j * 4 + i];
  Rt[3] = Rt[7] = Rt[11] = 0;
  dMassRotate(&composite, Rt);
  dBodySetPosition(otherBody, centre[0], centre[1], centre[2]);
  dBodySetMass(otherBody, &composite);

  for (const auto& [geom, pose] : poses) seatAt(geom, otherBody, pose);

  if (ownBody_) dBodyDestroy(ownBody_);
  ownBody_ = nullptr;
  ++bodyChanges_;
  return true;
}

void AbstractObject::setData(const void* data, std::size_t size) {
  data_.assign(static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + size);
  dGeomSetData(geom_, data_.data());
}

void AbstractObject::setPosition(double x, double y, double z) {
  if (const dBodyID body = getBody())
    dBodySetPosition(body, x, y, z);
  else
    dGeomSetPosition(geom_, x, y, z);
}

void AbstractObject::setLinearVelocity(double x, double y, double z) {
  if (const dBodyID body = getBody()) dBodySetLinearVel(body, x, y, z);
}

double AbstractObject::mass() const {
  const dBodyID body = getBody();
  if (!body) return 0.0;
  dMass m;
  dBodyGetMass(body, &m);
  return m.mass;
}

}  // namespace odelab
