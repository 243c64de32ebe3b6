#include "BulletShapes.h"

#include <algorithm>
#include <cmath>

#include "world/Engine.h"

namespace odelab::engines::bullet {

namespace {

using world::Geom;
using world::ShapeKind;

// One geom's own shape, centred on its own origin as ODE's are. Box and
// cylinder margins are left to Bullet (it shrinks them for small shapes).
std::unique_ptr<btCollisionShape> geomShape(const Geom& geom, int index) {
  std::unique_ptr<btCollisionShape> shape;
  switch (geom.shape) {
    case ShapeKind::Box:
      shape = std::make_unique<btBoxShape>(btVector3(geom.size[0], geom.size[1], geom.size[2]) * 0.5);
      break;
    case ShapeKind::Sphere:
      shape = std::make_unique<btSphereShape>(geom.size[0]);
      break;
    case ShapeKind::Capsule:  // ODE's capsule and cylinder lie along local z
      shape = std::make_unique<btCapsuleShapeZ>(geom.size[0], geom.size[1]);
      break;
    case ShapeKind::Cylinder:
      shape = std::make_unique<btCylinderShapeZ>(btVector3(geom.size[0], geom.size[0], geom.size[1] / 2));
      break;
    case ShapeKind::Plane:
      throw world::EngineError("geom " + std::to_string(index) + ": a plane must be static");
  }
  shape->setUserIndex(index);
  return shape;
}

double halfSize(const Geom& geom) {
  switch (geom.shape) {
    case ShapeKind::Box:
      return std::min({geom.size[0], geom.size[1], geom.size[2]}) / 2;
    case ShapeKind::Sphere:
    case ShapeKind::Capsule:
      return geom.size[0];
    case ShapeKind::Cylinder:
      return std::min(geom.size[0], geom.size[1] / 2);
    case ShapeKind::Plane:
      break;
  }
  return 0;
}

// The inertia tensor's principal moments and axes. Bullet holds only the
// three moments, so an off-diagonal tensor is diagonalised (Jacobi) and the
// body's Bullet frame turned onto the principal axes: the same tensor, exactly.
void principalFrame(const world::Body& body, BodyShape& out) {
  const auto& i = body.inertia;  // xx, yy, zz, xy, xz, yz
  if (i[3] == 0 && i[4] == 0 && i[5] == 0) {
    out.inertia = btVector3(i[0], i[1], i[2]);
    return;
  }
  btMatrix3x3 tensor(i[0], i[3], i[4], i[3], i[1], i[5], i[4], i[5], i[2]);
  btMatrix3x3 axes;  // tensor = axes * diagonal * axes^T
  tensor.diagonalize(axes, 1e-15, 100);
  out.inertia = btVector3(tensor[0][0], tensor[1][1], tensor[2][2]);
  axes.getRotation(out.principal);
}

bool isIdentity(const btTransform& t) {
  return t.getOrigin().isZero() && t.getRotation().dot(btQuaternion::getIdentity()) >= 1.0 - 1e-15;
}

}  // namespace

BodyShape makeBodyShape(const world::World& world, int body) {
  BodyShape out;
  principalFrame(world.bodies[body], out);
  const btTransform toPrincipal = btTransform(out.principal).inverse();
  std::vector<int> geoms;
  for (size_t g = 0; g < world.geoms.size(); ++g)
    if (world.geoms[g].body == body) geoms.push_back(static_cast<int>(g));
  if (geoms.empty()) {  // a body held by joints only
    out.shape = std::make_unique<btEmptyShape>();
    return out;
  }
  out.smallestHalfSize = halfSize(world.geoms[geoms[0]]);
  for (int g : geoms) out.smallestHalfSize = std::min(out.smallestHalfSize, halfSize(world.geoms[g]));
  // The geom's pose in the body's principal frame.
  auto poseOf = [&](const Geom& geom) {
    return toPrincipal * btTransform(toBt(geom.orientation), toBt(geom.position));
  };
  if (geoms.size() == 1 && isIdentity(poseOf(world.geoms[geoms[0]]))) {
    out.shape = geomShape(world.geoms[geoms[0]], geoms[0]);  // centred: no compound needed
    return out;
  }
  // Several geoms, or one off the centre of mass: a compound whose origin is
  // the centre of mass. Its own inertia estimate is never used (the body's
  // comes from the description).
  auto compound = std::make_unique<btCompoundShape>(false, static_cast<int>(geoms.size()));
  for (int g : geoms) {
    out.children.push_back(geomShape(world.geoms[g], g));
    compound->addChildShape(poseOf(world.geoms[g]), out.children.back().get());
  }
  compound->setUserIndex(-1);
  out.shape = std::move(compound);
  return out;
}

std::unique_ptr<btCollisionShape> makeStaticShape(const world::World& world, int index, btTransform& pose) {
  const Geom& geom = world.geoms[index];
  if (geom.shape != ShapeKind::Plane) {
    pose = btTransform(toBt(geom.orientation), toBt(geom.position));
    return geomShape(geom, index);
  }
  // a x + b y + c z = d is Bullet's plane of normal (a, b, c) and constant d.
  pose.setIdentity();
  auto plane = std::make_unique<btStaticPlaneShape>(btVector3(geom.plane[0], geom.plane[1], geom.plane[2]),
                                                    geom.plane[3]);
  plane->setUserIndex(index);
  return plane;
}

void noteShapeLimits(const world::World& world, Notes& notes) {
  bool box = false, capsule = false, cylinder = false;
  for (const Geom& g : world.geoms) {
    box = box || g.shape == ShapeKind::Box;
    capsule = capsule || g.shape == ShapeKind::Capsule;
    cylinder = cylinder || g.shape == ShapeKind::Cylinder;
  }
  // Box-box, box-sphere and anything-plane contacts are exact in Bullet;
  // other convex pairs go through GJK, whose collision margin rounds edges.
  if (cylinder)
    notes.add("cylinders collide through Bullet's convex (GJK) collision with a collision margin of up to 0.04 m "
              "that rounds their edges");
  if (box && (capsule || cylinder))
    notes.add("a box against a capsule or cylinder collides through Bullet's convex (GJK) collision with a "
              "collision margin of up to 0.04 m that rounds the box's edges");
}

}  // namespace odelab::engines::bullet
