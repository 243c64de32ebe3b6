#pragma once

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "Box.h"
#include "shared/BodyMeasures.h"
#include "shared/SceneConstants.h"

namespace odelab {

// test5's measurement of its pile: which dropped plates have landed, how
// high and how straight the stack stands, and where the next plate may be
// dropped. The scene owns the plates' bodies; this keeps pointers to them,
// valid until the scene is rebuilt (clear()).
class PlateStack {
 public:
  void clear() {
    plates_.clear();
    firstInAir_ = 0;
  }
  void add(Box* box, double bornAt) { plates_.push_back({box, bornAt, false}); }
  std::size_t size() const { return plates_.size(); }

  // Only plates from the oldest one not yet landed on are checked, so the
  // cost per step stays with the few falling plates, not the whole stack.
  // A plate can come to rest on one still rocking below it: the one below
  // is checked again until it is still too.
  void markLanded(double simulatedTime) {
    using namespace scene::test5;
    for (std::size_t i = firstInAir_; i < plates_.size(); ++i) {
      Plate& plate = plates_[i];
      if (plate.landed) continue;
      if (simulatedTime - plate.bornAt < LANDING_MIN_AGE || speedOf(plate.box->getBody()) > LANDED_SPEED) continue;
      plate.landed = true;
    }
    while (firstInAir_ < plates_.size() && plates_[firstInAir_].landed) ++firstInAir_;
  }

  // 6 m, or 1 m above the stack once it nears 6 m, and clear of falling plates.
  double spawnHeight() const {
    using namespace scene::test5;
    double drop = std::max(SPAWN_HEIGHT, height() + SPAWN_ABOVE_STACK);
    for (const Plate& plate : plates_)
      if (!plate.landed) drop = std::max(drop, plate.box->getPosition()[1] + MIN_SPAWN_SEPARATION);
    return drop;
  }

  // Top face of the highest landed plate, where it is now (the stack settles
  // under the weight of later plates).
  double height() const {
    double top = 0.0;
    for (const Plate& plate : plates_)
      if (plate.landed) top = std::max(top, plate.box->getPosition()[1] + scene::test5::PLATE_THICKNESS / 2);
    return top;
  }

  // Plates auto-disable has put to rest away from the stack: disabled, with
  // their bottom face more than FROZEN_GAP above the top of the next lower
  // plate (or the platform). Always 0 without auto-disable.
  int frozenInAirCount() const {
    using namespace scene::test5;
    std::vector<std::pair<double, bool>> plates;  // centre height, disabled
    for (const Plate& plate : plates_)
      plates.push_back({plate.box->getPosition()[1], !dBodyIsEnabled(plate.box->getBody())});
    std::sort(plates.begin(), plates.end());
    int frozen = 0;
    double below = 0.0;  // top of the platform, then of each plate
    for (const auto& [y, disabled] : plates) {
      if (disabled && y - PLATE_THICKNESS / 2 > below + FROZEN_GAP) ++frozen;
      below = y + PLATE_THICKNESS / 2;
    }
    return frozen;
  }

  int landedCount() const {
    return static_cast<int>(std::count_if(plates_.begin(), plates_.end(), [](const Plate& p) { return p.landed; }));
  }

  // Largest turn of a plate about the vertical from how it was dropped (square
  // plates: 0 to 45 degrees), the "twist" the thesis saw with CFM > 0.
  double maxTwistDegrees() const {
    double largest = 0.0;
    for (const Plate& plate : plates_) {
      const dReal* r = dBodyGetRotation(plate.box->getBody());  // local x in world: (r[0], r[4], r[8])
      double yaw = std::fabs(std::atan2(-r[8], r[0])) * 180.0 / M_PI;
      yaw = std::fmod(yaw, 90.0);
      largest = std::max(largest, std::min(yaw, 90.0 - yaw));
    }
    return largest;
  }

  // Largest horizontal distance of a plate centre from the axis x = z = 0.
  double maxAxisOffset() const {
    double largest = 0.0;
    for (const Plate& plate : plates_) {
      const dReal* p = plate.box->getPosition();
      largest = std::max(largest, std::hypot(p[0], p[2]));
    }
    return largest;
  }

 private:
  struct Plate {
    Box* box;
    double bornAt;
    bool landed;
  };

  std::vector<Plate> plates_;
  std::size_t firstInAir_ = 0;  // plates_ before it have all landed
};

}  // namespace odelab
