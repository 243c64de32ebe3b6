#pragma once

// The world's geoms as Bullet collision shapes: one body's geoms become one
// shape in the body's principal frame (Bullet keeps a body's inertia as three
// principal moments, so its frame must be the principal frame), and each
// static geom a shape of its own. Every shape that touches carries its geom's
// index as its user index, which the contact callback reads.

#include <memory>
#include <vector>

#include "BulletCommon.h"

namespace odelab::engines::bullet {

struct BodyShape {
  std::unique_ptr<btCollisionShape> shape;                  // one geom's shape, or a compound
  std::vector<std::unique_ptr<btCollisionShape>> children;  // a compound's, kept alive here
  btVector3 inertia{1, 1, 1};  // principal moments about the centre of mass
  // The principal frame's rotation in the description's body frame: Bullet's
  // orientation is the description's times this.
  btQuaternion principal = btQuaternion::getIdentity();
  double smallestHalfSize = 0;  // of its geoms (0 when it has none), for continuous collision
};

BodyShape makeBodyShape(const world::World& world, int body);

// A static geom's shape and its pose in the world.
std::unique_ptr<btCollisionShape> makeStaticShape(const world::World& world, int geom, btTransform& pose);

// What Bullet's collision does not reproduce exactly for the shapes in `world`.
void noteShapeLimits(const world::World& world, Notes& notes);

}  // namespace odelab::engines::bullet
