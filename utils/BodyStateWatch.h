#pragma once

#include <ode/ode.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "AbstractObject.h"

namespace odelab {

// The cheap test run after every step: is any body's position non-finite,
// or its speed or spin beyond the runaway bounds below? (NaN fails every
// comparison, so it counts as beyond.) It keeps the bodies' state vectors
// (dBodyGetPosition and kin, which ODE keeps in place while the set of
// bodies stays the same) and looks them up again only after
// AbstractObject::bodyChanges() moves, so a step costs a few
// multiplications a body and no calls.
class BodyStateWatch {
 public:
  using Objects = std::vector<std::unique_ptr<AbstractObject>>;

  // A blow-up that stays finite (runaway energy): no scene comes near these.
  // 1e8 m/s is ten times the fastest launch any scene allows (test10's
  // --velocity, at most 1e7 m/s); free fall at 1 g needs 118 days to reach it.
  // There is no bound on distance: a body that falls off a platform (test4,
  // test5) is 1e8 m down after 75 minutes, which a window session can last.
  static constexpr double RUNAWAY_SPEED = 1e8;  // m/s
  static constexpr double RUNAWAY_SPIN = 1e8;   // rad/s

  // NaN fails every comparison, infinity the bounds: both count as suspicious.
  bool suspicious(const Objects& objects) const {
    constexpr double maxSpeed2 = RUNAWAY_SPEED * RUNAWAY_SPEED, maxSpin2 = RUNAWAY_SPIN * RUNAWAY_SPIN;
    if (seen_ != AbstractObject::bodyChanges()) refresh(objects);
    for (const State& body : bodies_) {
      const dReal *p = body.position, *v = body.velocity, *w = body.spin;
      if (!(std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) <= std::numeric_limits<double>::max()) ||
          !(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= maxSpeed2) ||
          !(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] <= maxSpin2))
        return true;
    }
    return false;
  }

 private:
  struct State {
    const dReal *position, *velocity, *spin;
  };
  void refresh(const Objects& objects) const;

  mutable std::vector<State> bodies_;
  mutable std::uint64_t seen_ = ~std::uint64_t{0};
};

}  // namespace odelab
