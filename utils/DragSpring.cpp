#include "DragSpring.h"

#include <cmath>

namespace odelab {

PickHit pickObject(const std::vector<std::unique_ptr<AbstractObject>>& objects, const double origin[3],
                   const double direction[3], double maxDistance) {
  PickHit best;
  dGeomID ray = dCreateRay(nullptr, maxDistance);
  dGeomRaySet(ray, origin[0], origin[1], origin[2], direction[0], direction[1], direction[2]);
  for (size_t i = 0; i < objects.size(); ++i) {
    const AbstractObject& object = *objects[i];
    if (object.isFixed() || !object.visible) continue;
    dContactGeom contact;
    if (dCollide(ray, object.getGeom(), 1, &contact, sizeof contact) <= 0) continue;
    if (best.objectIndex >= 0 && contact.depth >= best.distance) continue;
    best.objectIndex = static_cast<int>(i);
    best.distance = contact.depth;  // for a ray, depth is the distance along it
    for (int k = 0; k < 3; ++k) best.point[k] = contact.pos[k];
  }
  dGeomDestroy(ray);
  return best;
}

void DragSpring::apply(dBodyID body, const double grabLocal[3], const double target[3], double gravity,
                       double applied[3], double appliedAt[3]) {
  dMass mass;
  dBodyGetMass(body, &mass);
  const double omega = 2.0 * M_PI * FREQUENCY_HZ;
  const double stiffness = mass.mass * omega * omega;
  const double damping = 2.0 * mass.mass * omega;
  dVector3 point, velocity;
  dBodyGetRelPointPos(body, grabLocal[0], grabLocal[1], grabLocal[2], point);
  dBodyGetRelPointVel(body, grabLocal[0], grabLocal[1], grabLocal[2], velocity);
  double force[3];
  double magnitude = 0.0;
  for (int k = 0; k < 3; ++k) {
    force[k] = stiffness * (target[k] - point[k]) - damping * velocity[k];
    magnitude += force[k] * force[k];
  }
  magnitude = std::sqrt(magnitude);
  const double cap = MAX_FORCE_IN_WEIGHTS * mass.mass * std::max(gravity, 1.0);
  const double scale = magnitude > cap ? cap / magnitude : 1.0;
  for (int k = 0; k < 3; ++k) {
    applied[k] = force[k] * scale;
    appliedAt[k] = point[k];
  }
  dBodyEnable(body);
  dBodyAddForceAtPos(body, applied[0], applied[1], applied[2], point[0], point[1], point[2]);
}

void DragSpring::grabbedPoint(dBodyID body, const double grabLocal[3], double point[3]) {
  dVector3 p;
  dBodyGetRelPointPos(body, grabLocal[0], grabLocal[1], grabLocal[2], p);
  for (int k = 0; k < 3; ++k) point[k] = p[k];
}

double DragSpring::distance(dBodyID body, const double grabLocal[3], const double target[3]) {
  dVector3 point;
  dBodyGetRelPointPos(body, grabLocal[0], grabLocal[1], grabLocal[2], point);
  return std::sqrt((target[0] - point[0]) * (target[0] - point[0]) + (target[1] - point[1]) * (target[1] - point[1]) +
                   (target[2] - point[2]) * (target[2] - point[2]));
}

}  // namespace odelab
