#include "BulletJoints.h"

#include <cmath>

#include "world/Engine.h"

namespace odelab::engines::bullet {

namespace {

using world::Joint;

btRigidBody& orWorld(btRigidBody* body) { return body ? *body : btTypedConstraint::getFixedBody(); }

// A world frame whose `column` axis is `axis` (right-handed), at `origin`.
btTransform frameAlong(const btVector3& axis, int column, const btVector3& origin) {
  const btVector3 n = axis.normalized();
  btVector3 p, q;
  btPlaneSpace1(n, p, q);  // n, p, q right-handed
  btVector3 c[3];
  c[column] = n;
  c[(column + 1) % 3] = p;
  c[(column + 2) % 3] = q;
  btMatrix3x3 basis(c[0].x(), c[1].x(), c[2].x(), c[0].y(), c[1].y(), c[2].y(), c[0].z(), c[1].z(), c[2].z());
  return btTransform(basis, origin);
}

// The world frame `frame` in the body's own (Bullet) frame.
btTransform inBody(btRigidBody& body, const btTransform& frame) { return body.getWorldTransform().inverse() * frame; }

double finiteOr(double value, double instead) { return std::isinf(value) ? instead : value; }

std::unique_ptr<btTypedConstraint> ball(const Joint& joint, btRigidBody& a, btRigidBody& b) {
  const btVector3 anchor = toBt(joint.anchor);
  auto c = std::make_unique<btPoint2PointConstraint>(a, b, a.getWorldTransform().inverse() * anchor,
                                                     b.getWorldTransform().inverse() * anchor);
  if (!std::isnan(joint.erp)) c->setParam(BT_CONSTRAINT_ERP, joint.erp);
  if (!std::isnan(joint.cfm)) c->setParam(BT_CONSTRAINT_CFM, joint.cfm);
  return c;
}

// Bullet's hinge angle is A's rotation relative to B about the frame's z
// axis, zero as built: with A = body1 it is ODE's hinge angle.
std::unique_ptr<btTypedConstraint> hinge(const Joint& joint, btRigidBody& a, btRigidBody& b) {
  const btTransform frame = frameAlong(toBt(joint.axis), 2, toBt(joint.anchor));
  auto c = std::make_unique<btHingeConstraint>(a, b, inBody(a, frame), inBody(b, frame), false);
  if (!std::isinf(joint.lowStop) || !std::isinf(joint.highStop)) {
    // Hard stops as ODE's: error corrected at the joint's ERP (bias 1),
    // no bounce (relaxation 0; Bullet's default 1 would bounce).
    c->setLimit(finiteOr(joint.lowStop, -SIMD_PI), finiteOr(joint.highStop, SIMD_PI), 0.9, 1.0, 0.0);
  }
  if (!std::isnan(joint.erp)) c->setParam(BT_CONSTRAINT_ERP, joint.erp);
  if (!std::isnan(joint.cfm)) c->setParam(BT_CONSTRAINT_CFM, joint.cfm);
  return c;
}

// Bullet's slider position is B's origin minus A's along the frame's x axis:
// with A = body2 and B = body1 it is ODE's slider position (body1 - body2).
std::unique_ptr<btTypedConstraint> slider(const Joint& joint, btRigidBody& body1, btRigidBody& body2) {
  const btVector3 origin = (&body1 != &btTypedConstraint::getFixedBody() ? body1 : body2).getWorldTransform().getOrigin();
  const btTransform frame = frameAlong(toBt(joint.axis), 0, origin);
  auto c = std::make_unique<btSliderConstraint>(body2, body1, inBody(body2, frame), inBody(body1, frame), true);
  const bool limited = !std::isinf(joint.lowStop) || !std::isinf(joint.highStop);
  c->setLowerLinLimit(limited ? finiteOr(joint.lowStop, -BT_LARGE_FLOAT) : 1.0);  // lower > upper: free
  c->setUpperLinLimit(limited ? finiteOr(joint.highStop, BT_LARGE_FLOAT) : -1.0);
  c->setLowerAngLimit(0);  // no rotation about the axis, as ODE's slider
  c->setUpperAngLimit(0);
  for (int axis : {1, 3, 4}) {  // the rows that hold the joint (0 is the stop along it)
    if (!std::isnan(joint.erp)) c->setParam(BT_CONSTRAINT_STOP_ERP, joint.erp, axis);
    if (!std::isnan(joint.cfm)) c->setParam(BT_CONSTRAINT_STOP_CFM, joint.cfm, axis);
  }
  return c;
}

std::unique_ptr<btTypedConstraint> fixed(const Joint& joint, btRigidBody& a, btRigidBody& b) {
  const btRigidBody& at = &b != &btTypedConstraint::getFixedBody() ? b : a;
  const btTransform frame(btQuaternion::getIdentity(), at.getWorldTransform().getOrigin());
  auto c = std::make_unique<btFixedConstraint>(a, b, inBody(a, frame), inBody(b, frame));
  // Bullet's fixed joint is six locked axes: each held like a stop.
  for (int axis = 0; axis < 6; ++axis) {
    if (!std::isnan(joint.erp)) c->setParam(BT_CONSTRAINT_STOP_ERP, joint.erp, axis);
    if (!std::isnan(joint.cfm)) c->setParam(BT_CONSTRAINT_STOP_CFM, joint.cfm, axis);
  }
  return c;
}

}  // namespace

std::unique_ptr<btTypedConstraint> makeJoint(const Joint& joint, btRigidBody* body1, btRigidBody* body2) {
  if (!body1 && !body2) throw world::EngineError("a joint between the static world and itself");
  btRigidBody& a = orWorld(body1);
  btRigidBody& b = orWorld(body2);
  switch (joint.kind) {
    case world::JointKind::Ball:
      return ball(joint, a, b);
    case world::JointKind::Hinge:
      return hinge(joint, a, b);
    case world::JointKind::Slider:
      return slider(joint, a, b);
    case world::JointKind::Fixed:
      return fixed(joint, a, b);
  }
  throw world::EngineError("a joint of unknown type");
}

}  // namespace odelab::engines::bullet
