#pragma once

// The world's joints as Bullet constraints. Each is built from the bodies'
// poses now (the description's anchor and axis are world values as built),
// with the static world as Bullet's fixed body, and measures its angle or
// position with ODE's sign: body1 relative to body2.

#include <memory>

#include "BulletCommon.h"

namespace odelab::engines::bullet {

// `body1`, `body2`: the joint's Bullet bodies, nullptr for the static world.
std::unique_ptr<btTypedConstraint> makeJoint(const world::Joint& joint, btRigidBody* body1, btRigidBody* body2);

}  // namespace odelab::engines::bullet
