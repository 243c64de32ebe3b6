#pragma once

// Readings every peer takes the same way from a body's pose: the tilt of its
// local y axis and how far a cube's lowest corner lies below the ground.
// `yRow`: the world-y row of the body's rotation matrix (how far each local
// axis reaches up).

#include <algorithm>
#include <cmath>

#include "PeerScene.h"

namespace odelab::peers {

inline double tiltDegrees(const double yRow[3]) {
  return std::acos(std::max(-1.0, std::min(1.0, yRow[1]))) * 180.0 / M_PI;
}

// m below y = 0 (0 when above): each local axis reaches |its world y| x half the side.
inline double depthBelowGround(const Vec3& centre, const double yRow[3], double side) {
  const double reach = side / 2 * (std::fabs(yRow[0]) + std::fabs(yRow[1]) + std::fabs(yRow[2]));
  return std::max(0.0, reach - centre.y);
}

}  // namespace odelab::peers
