// The measures that follow geometry rather than totals: how far each joint's
// two halves have come apart, and which bodies passed through a thin wall.
#include <algorithm>
#include <cmath>
#include <limits>

#include "WorldMeasures.h"

namespace odelab::world {

namespace {

// A point or direction as `body` carries it: in its frame, or the world's for the static side.
void toBody(dBodyID body, const double* world, bool point, dVector3 out) {
  if (!body) {
    std::copy(world, world + 3, out);
  } else if (point) {
    dBodyGetPosRelPoint(body, world[0], world[1], world[2], out);
  } else {
    dBodyVectorFromWorld(body, world[0], world[1], world[2], out);
  }
}

void toWorld(dBodyID body, const dVector3 local, bool point, dVector3 out) {
  if (!body) {
    std::copy(local, local + 3, out);
  } else if (point) {
    dBodyGetRelPointPos(body, local[0], local[1], local[2], out);
  } else {
    dBodyVectorToWorld(body, local[0], local[1], local[2], out);
  }
}

// The rotation of body 2 relative to body 1 (the world's for a static side).
void relativeTurn(dBodyID body1, dBodyID body2, dQuaternion out) {
  dQuaternion q1 = {1, 0, 0, 0}, q2 = {1, 0, 0, 0};
  if (body1) std::copy(dBodyGetQuaternion(body1), dBodyGetQuaternion(body1) + 4, q1);
  if (body2) std::copy(dBodyGetQuaternion(body2), dBodyGetQuaternion(body2) + 4, q2);
  dQMultiply1(out, q1, q2);  // q1^-1 q2
}

double angleBetween(const dVector3 a, const dVector3 b) {
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  return std::acos(std::clamp(dot / (na * nb), -1.0, 1.0));
}

}  // namespace

void WorldMeasures::watchJoints() {
  for (const Joint& j : world_.joints) {
    JointWatch w{};
    w.body1 = j.body1 < 0 ? nullptr : bodies_[static_cast<size_t>(j.body1)];
    w.body2 = j.body2 < 0 ? nullptr : bodies_[static_cast<size_t>(j.body2)];
    // The point both halves hold together: the anchor; for a slider or fixed
    // joint (no anchor), body 2's centre.
    const bool anchored = j.kind == JointKind::Ball || j.kind == JointKind::Hinge;
    const double* point = anchored ? j.anchor.data() : dBodyGetPosition(w.body2 ? w.body2 : w.body1);
    toBody(w.body1, point, true, w.anchor1);
    toBody(w.body2, point, true, w.anchor2);
    w.hasAxis = j.kind == JointKind::Hinge || j.kind == JointKind::Slider;
    toBody(w.body1, j.axis.data(), false, w.axis1);
    toBody(w.body2, j.axis.data(), false, w.axis2);
    w.keepsTurn = j.kind == JointKind::Fixed || j.kind == JointKind::Slider;
    relativeTurn(w.body1, w.body2, w.relative);
    joints_.push_back(w);
  }
}

void WorldMeasures::jointErrors() {
  for (const JointWatch& w : joints_) {
    dVector3 a1, a2, x1, x2;
    toWorld(w.body1, w.anchor1, true, a1);
    toWorld(w.body2, w.anchor2, true, a2);
    toWorld(w.body1, w.axis1, false, x1);
    toWorld(w.body2, w.axis2, false, x2);
    dVector3 gap = {a2[0] - a1[0], a2[1] - a1[1], a2[2] - a1[2]};
    if (w.keepsTurn && w.hasAxis) {  // a slider: only the gap across its axis is an error
      const double n = std::sqrt(x1[0] * x1[0] + x1[1] * x1[1] + x1[2] * x1[2]);
      const double along = (gap[0] * x1[0] + gap[1] * x1[1] + gap[2] * x1[2]) / (n * n);
      for (int k = 0; k < 3; ++k) gap[k] -= along * x1[k];
    }
    jointError_ = std::max(jointError_, std::sqrt(gap[0] * gap[0] + gap[1] * gap[1] + gap[2] * gap[2]));
    if (w.hasAxis) axisError_ = std::max(axisError_, angleBetween(x1, x2));
    if (w.keepsTurn) {
      dQuaternion now, change;
      relativeTurn(w.body1, w.body2, now);
      dQMultiply1(change, w.relative, now);
      axisError_ = std::max(axisError_, 2.0 * std::acos(std::min(1.0, std::abs(static_cast<double>(change[0])))));
    }
  }
}

void WorldMeasures::tunnelling() {
  const Measure& m = *std::find_if(world_.measures.begin(), world_.measures.end(),
                                   [](const Measure& x) { return x.kind == MeasureKind::Tunnelling; });
  const Geom& wall = world_.geoms[static_cast<size_t>(m.geom)];
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (!bodies_[i]) continue;
    const dReal* c = dBodyGetPosition(bodies_[i]);
    double side = std::numeric_limits<double>::quiet_NaN();
    if (wall.shape == ShapeKind::Plane) {
      side = wall.plane[0] * c[0] + wall.plane[1] * c[1] + wall.plane[2] * c[2] - wall.plane[3];
    } else {
      // The box's frame: the centre's coordinates; its thinnest side is the wall's normal.
      dMatrix3 r;
      const dQuaternion q = {wall.orientation[0], wall.orientation[1], wall.orientation[2], wall.orientation[3]};
      dRfromQ(r, q);
      const double d[3] = {c[0] - wall.position[0], c[1] - wall.position[1], c[2] - wall.position[2]};
      double local[3];
      for (int k = 0; k < 3; ++k) local[k] = r[0 * 4 + k] * d[0] + r[1 * 4 + k] * d[1] + r[2 * 4 + k] * d[2];
      const int thin = static_cast<int>(std::min_element(wall.size.begin(), wall.size.end()) - wall.size.begin());
      bool facing = true;  // within the wall's extent across its normal
      for (int k = 0; k < 3; ++k)
        if (k != thin && std::abs(local[k]) > wall.size[static_cast<size_t>(k)] / 2) facing = false;
      if (facing) side = local[thin];
    }
    const double before = side_[i];
    if (!std::isnan(before) && !std::isnan(side) && (before > 0) != (side > 0)) {
      ++crossings_;
      tunnelled_[i] = true;
    }
    side_[i] = side;
  }
}

}  // namespace odelab::world
