#pragma once

// The little rigid-body algebra the MuJoCo adapter needs to place bodies in
// MuJoCo's kinematic tree (poses relative to a parent) and to turn a body's
// world state into joint coordinates. Quaternions are [w, x, y, z], as in
// the world description and in MuJoCo.

#include <cmath>

#include "world/WorldDescription.h"

namespace odelab::engines::mujoco {

using world::Quat;
using world::Vec3;

inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

inline Quat conj(const Quat& q) { return {q[0], -q[1], -q[2], -q[3]}; }
inline Quat mul(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
inline Quat normalized(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return n > 0 ? Quat{q[0] / n, q[1] / n, q[2] / n, q[3] / n} : Quat{1, 0, 0, 0};
}
// v turned by the unit quaternion q.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
  const Vec3 u{q[1], q[2], q[3]};
  const Vec3 t = scale(cross(u, v), 2.0);
  return add(add(v, scale(t, q[0])), cross(u, t));
}

// A frame: where its origin is and how it is turned, in its parent's frame.
struct Pose {
  Vec3 position{0, 0, 0};
  Quat orientation{1, 0, 0, 0};
};

// `b`, given in the frame `a`, expressed in a's parent frame.
inline Pose compose(const Pose& a, const Pose& b) {
  return {add(a.position, rotate(a.orientation, b.position)), mul(a.orientation, b.orientation)};
}
inline Pose inverse(const Pose& a) {
  const Quat c = conj(a.orientation);
  return {scale(rotate(c, a.position), -1.0), c};
}
// A world point in the frame `a`.
inline Vec3 pointIn(const Pose& a, const Vec3& p) { return rotate(conj(a.orientation), sub(p, a.position)); }

}  // namespace odelab::engines::mujoco
