#pragma once

#include <algorithm>
#include <cmath>

namespace odelab {

// Says when a row of an output file is due: at simulated times 0, interval,
// 2 * interval, ... Grid points are counted, not summed, so the rows stay on
// the grid over long runs; a step longer than the interval (F8) skips the
// grid points it jumps over and the row carries the actual time.
class FixedIntervalSampler {
 public:
  explicit FixedIntervalSampler(double interval) : interval_(interval) {}

  double interval() const { return interval_; }
  void restart() { next_ = 0; }

  // True once per grid point reached. Simulated time is a sum of steps, so a
  // grid point counts as reached within half a step of it.
  bool due(double time, double step) {
    const double reach = time + 0.5 * step;
    if (reach < next_ * interval_) return false;
    // Jump to the first grid point after `reach` (counting them one by one
    // spun for ever with a tiny interval), then settle any rounding.
    next_ = std::max(next_ + 1, static_cast<long>(std::floor(reach / interval_)));
    while (next_ * interval_ <= reach) ++next_;
    return true;
  }

 private:
  double interval_;
  long next_ = 0;
};

}  // namespace odelab
