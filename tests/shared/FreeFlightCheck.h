#pragma once

// test10's check that a launched cube flew free until the wall: a first
// step that cannot reach the wall, whatever the cube's turn, must take it at
// least 99% of v h. Less means something slowed it in free flight (another
// engine's speed cap, --engine), and what followed tested the cap, not the
// wall. A launch whose first step could reach the wall is not judged (the
// wall, or test10's own sweep, may stop it there): a cap above about
// 3400 m/s at step 0.001 goes unseen.

#include <cmath>
#include <vector>

#include "Box.h"
#include "SceneConstants.h"

namespace odelab::scene::test10 {

class FreeFlightCheck {
 public:
  void launched(const Box* cube, double startX, double velocity) { pending_.push_back({cube, startX, velocity}); }
  // After every step: the launches of the step before, looked at once.
  void afterStep(double step) {
    for (const Pending& p : pending_) {
      const double x = p.cube->getPosition()[0];
      const double reach = CUBE_SIDE * std::sqrt(3.0) / 2;  // its farthest corner, however turned
      const bool freeStep = p.startX + p.velocity * step + reach < WALL_NEAR_FACE;
      if (freeStep && x - p.startX < 0.99 * p.velocity * step) ++slowed_;
    }
    pending_.clear();
  }
  void clear() {
    pending_.clear();
    slowed_ = asked_ = 0;
  }
  int slowed() const { return slowed_; }  // launches slowed before the wall so far
  // Whether a launch was slowed since the last time this was asked.
  bool slowedSinceAsked() {
    const bool more = slowed_ > asked_;
    asked_ = slowed_;
    return more;
  }

 private:
  struct Pending {
    const Box* cube;
    double startX;
    double velocity;
  };
  std::vector<Pending> pending_;
  int slowed_ = 0;
  int asked_ = 0;
};

}  // namespace odelab::scene::test10
