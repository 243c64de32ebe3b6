#pragma once

namespace odelab {

// The thesis's frame-to-steps accumulator: each frame's elapsed real time is
// clamped to MAXIMUM_ELAPSED_TIME (so a slow machine runs slower than real
// time instead of spiralling), added to timeCache, and whole steps are taken
// while timeCache >= step. The remainder carries to the next frame.
class FixedStepClock {
 public:
  static constexpr double MAXIMUM_ELAPSED_TIME = 1.0 / 100.0;

  // Returns how many steps of `step` seconds to run for this frame. The
  // clamped frame time is multiplied by `timeScale` (slow motion below 1).
  int advance(double elapsedSeconds, double step, double timeScale = 1.0);

  double timeCache() const { return timeCache_; }
  void reset() { timeCache_ = 0.0; }

 private:
  double timeCache_ = 0.0;
};

}  // namespace odelab
