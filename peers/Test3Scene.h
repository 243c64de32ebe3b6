#pragma once

// test3's domino spiral as the peers build it: test3's constants
// (tests/shared/SceneConstants.h), the same placements along the spiral and
// the same push on the first domino as tests/scenes/test3_domino.cpp makes
// (that program keeps its placement code to itself, so the peers' is here;
// the same-scene check compares the two programs' figures).

#include <cmath>
#include <vector>

#include "../tests/shared/SceneConstants.h"
#include "PeerScene.h"

namespace odelab::peers::test3 {

using namespace odelab::scene::test3;

// One domino as built: its centre, its orientation (quaternion w, x, y, z:
// the yaw that turns its thickness along the path, then the lean forward
// about its leading bottom edge), and its start velocities (the first one's push).
struct DominoStart {
  Vec3 centre;
  double quaternion[4];
  Vec3 velocity, spin;
};

inline Vec3 rotate(const double q[4], const Vec3& v) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  // v + 2 r x (r x v + w v), r = (x, y, z)
  const Vec3 c{y * v.z - z * v.y + w * v.x, z * v.x - x * v.z + w * v.y, x * v.y - y * v.x + w * v.z};
  return {v.x + 2 * (y * c.z - z * c.y), v.y + 2 * (z * c.x - x * c.z), v.z + 2 * (x * c.y - y * c.x)};
}

// The dominoes along the Archimedean spiral r = START + PITCH angle / 2 pi,
// DOMINO_SPACING apart in arc length, from the inside out.
inline std::vector<DominoStart> dominoStarts(int count) {
  std::vector<DominoStart> starts;
  const double growth = SPIRAL_PITCH / (2 * M_PI);
  double angle = 0.0;
  for (int i = 0; i < count; ++i) {
    const double r = SPIRAL_START_RADIUS + growth * angle;
    const double c = std::cos(angle), s = std::sin(angle);
    const double dx = growth * c - r * s, dz = growth * s + r * c, length = std::hypot(dx, dz);
    const double tx = dx / length, tz = dz / length;
    angle += DOMINO_SPACING / length;
    const double yaw = std::atan2(-tz, tx) / 2, lean = (i == 0 ? FIRST_TILT_DEGREES : 0.0) * M_PI / 360.0;
    // lean (about (tz, 0, -tx)) after yaw (about y)
    const double a[4] = {std::cos(lean), tz * std::sin(lean), 0.0, -tx * std::sin(lean)};
    const double b[4] = {std::cos(yaw), 0.0, std::sin(yaw), 0.0};
    DominoStart d{};
    d.quaternion[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    d.quaternion[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    d.quaternion[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    d.quaternion[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    // The leading bottom edge stays on the ground at the pivot.
    const Vec3 pivot{r * c + tx * DOMINO_THICKNESS / 2, 0.0, r * s + tz * DOMINO_THICKNESS / 2};
    const Vec3 arm = rotate(d.quaternion, {-DOMINO_THICKNESS / 2, DOMINO_HEIGHT / 2, 0.0});
    d.centre = {pivot.x + arm.x, arm.y, pivot.z + arm.z};
    if (i == 0) {  // turning about the leading edge at FIRST_PUSH: v = omega x arm
      d.spin = {FIRST_PUSH * tz, 0.0, -FIRST_PUSH * tx};
      d.velocity = {d.spin.y * arm.z - d.spin.z * arm.y, d.spin.z * arm.x - d.spin.x * arm.z,
                    d.spin.x * arm.y - d.spin.y * arm.x};
    }
    starts.push_back(d);
  }
  return starts;
}

}  // namespace odelab::peers::test3
