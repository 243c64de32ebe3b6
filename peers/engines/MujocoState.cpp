#include "MujocoState.h"

#include <cmath>

namespace odelab::engines::mujoco {

namespace {

using world::BodyState;

Vec3 vec3(const mjtNum* v) { return {v[0], v[1], v[2]}; }

Pose poseOf(const mjData* d, int mjBody) {
  return {vec3(d->xpos + 3 * mjBody), {d->xquat[4 * mjBody], d->xquat[4 * mjBody + 1], d->xquat[4 * mjBody + 2],
                                       d->xquat[4 * mjBody + 3]}};
}

// [angular, linear] in world axes, at the body's origin.
void velocityOf(const mjModel* m, const mjData* d, int mjBody, Vec3& angular, Vec3& linear) {
  mjtNum v[6];
  mj_objectVelocity(m, d, mjOBJ_BODY, mjBody, v, 0);
  angular = vec3(v);
  linear = vec3(v + 3);
}

}  // namespace

void refreshKinematics(const mjModel* m, mjData* d) {
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
}

BodyState readBody(const mjModel* m, const mjData* d, int mjBody) {
  BodyState s;
  const Pose pose = poseOf(d, mjBody);
  s.position = pose.position;
  s.orientation = pose.orientation;
  velocityOf(m, d, mjBody, s.angularVelocity, s.linearVelocity);
  return s;  // MuJoCo 2.2 has no sleeping: always enabled
}

void writeFreeBody(const mjModel* m, mjData* d, int mjBody, const BodyState& desired) {
  const int joint = m->body_jntadr[mjBody];
  mjtNum* q = d->qpos + m->jnt_qposadr[joint];
  mjtNum* v = d->qvel + m->jnt_dofadr[joint];
  const Quat orientation = normalized(desired.orientation);
  for (int i = 0; i < 3; ++i) q[i] = desired.position[static_cast<size_t>(i)];
  for (int i = 0; i < 4; ++i) q[3 + i] = orientation[static_cast<size_t>(i)];
  // A free joint's linear velocity is in world axes, its angular velocity in the body's own.
  const Vec3 local = rotate(conj(orientation), desired.angularVelocity);
  for (int i = 0; i < 3; ++i) {
    v[i] = desired.linearVelocity[static_cast<size_t>(i)];
    v[3 + i] = local[static_cast<size_t>(i)];
  }
}

void writeJointCoordinates(const mjModel* m, mjData* d, const Mount& mount, world::JointKind kind, int mjBody,
                           int mjParent, const BodyState& desired) {
  if (kind == world::JointKind::Fixed) return;  // welded: nothing to choose
  Pose parent;
  Vec3 parentAngular{0, 0, 0}, parentLinear{0, 0, 0};
  if (mjParent > 0) {
    parent = poseOf(d, mjParent);
    velocityOf(m, d, mjParent, parentAngular, parentLinear);
  }
  // Where the body would be with its joint at 0, and how far it is turned from there.
  const Pose zero = compose(parent, mount.reference);
  const Quat turn = normalized(mul(conj(zero.orientation), normalized(desired.orientation)));
  const Vec3 relativeAngular = sub(desired.angularVelocity, parentAngular);
  const int joint = m->body_jntadr[mjBody];
  mjtNum* q = d->qpos + m->jnt_qposadr[joint];
  mjtNum* v = d->qvel + m->jnt_dofadr[joint];
  switch (kind) {
    case world::JointKind::Hinge: {
      // The turn's twist about the axis (its swing is what the joint cannot do).
      const Vec3 axis = mount.axis;
      double angle = 2.0 * std::atan2(dot({turn[1], turn[2], turn[3]}, axis), turn[0]);
      if (angle > M_PI) angle -= 2.0 * M_PI;
      if (angle <= -M_PI) angle += 2.0 * M_PI;
      q[0] = angle;
      v[0] = dot(relativeAngular, rotate(zero.orientation, axis));
      return;
    }
    case world::JointKind::Ball: {
      for (int i = 0; i < 4; ++i) q[i] = turn[static_cast<size_t>(i)];
      // A ball joint's rate is the angular velocity relative to the parent, in the body's own axes.
      const Vec3 local = rotate(conj(normalized(desired.orientation)), relativeAngular);
      for (int i = 0; i < 3; ++i) v[i] = local[static_cast<size_t>(i)];
      return;
    }
    case world::JointKind::Slider: {
      const Vec3 axis = rotate(zero.orientation, mount.axis);
      q[0] = dot(sub(desired.position, zero.position), axis);
      const Vec3 carried = add(parentLinear, cross(parentAngular, sub(desired.position, parent.position)));
      v[0] = dot(sub(desired.linearVelocity, carried), axis);
      return;
    }
    case world::JointKind::Fixed:
      return;
  }
}

Coordinates coordinatesOf(const mjModel* m, const mjData* d, int mjBody) {
  Coordinates c;
  if (m->body_jntnum[mjBody] == 0) return c;
  const int joint = m->body_jntadr[mjBody];
  int qsize = 1, vsize = 1;
  if (m->jnt_type[joint] == mjJNT_FREE) qsize = 7, vsize = 6;
  if (m->jnt_type[joint] == mjJNT_BALL) qsize = 4, vsize = 3;
  c.qpos.assign(d->qpos + m->jnt_qposadr[joint], d->qpos + m->jnt_qposadr[joint] + qsize);
  c.qvel.assign(d->qvel + m->jnt_dofadr[joint], d->qvel + m->jnt_dofadr[joint] + vsize);
  return c;
}

void setCoordinates(const mjModel* m, mjData* d, int mjBody, const Coordinates& c) {
  if (m->body_jntnum[mjBody] == 0) return;
  const int joint = m->body_jntadr[mjBody];
  for (size_t i = 0; i < c.qpos.size(); ++i) d->qpos[static_cast<size_t>(m->jnt_qposadr[joint]) + i] = c.qpos[i];
  for (size_t i = 0; i < c.qvel.size(); ++i) d->qvel[static_cast<size_t>(m->jnt_dofadr[joint]) + i] = c.qvel[i];
}

}  // namespace odelab::engines::mujoco
