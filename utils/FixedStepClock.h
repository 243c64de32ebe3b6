#pragma once

namespace odelab {

// The thesis's frame-to-steps accumulator: each frame's elapsed real time is
// clamped to a maximum frame time (so one long hitch cannot ask for an
// unbounded number of steps), added to timeCache, and whole steps are taken
// while timeCache >= step. The remainder carries to the next frame.
//
// The thesis clamped to 1/100 s (THESIS_MAXIMUM_ELAPSED_TIME). That ran the
// simulation at FPS/100 of real time whenever frames took longer than 10 ms:
// 0.6x at a 60 Hz vsync. The default clamp is a quarter second, which no
// ordinary frame reaches; the window's stepping budget (TimeControl) is what
// protects the frame rate from costly settings.
class FixedStepClock {
 public:
  static constexpr double THESIS_MAXIMUM_ELAPSED_TIME = 1.0 / 100.0;
  static constexpr double DEFAULT_MAXIMUM_ELAPSED_TIME = 0.25;

  explicit FixedStepClock(double maximumElapsedTime = DEFAULT_MAXIMUM_ELAPSED_TIME)
      : maximumElapsedTime_(maximumElapsedTime) {}

  // Returns how many steps of `step` seconds to run for this frame. The
  // clamped frame time is multiplied by `timeScale` (slow motion below 1).
  int advance(double elapsedSeconds, double step, double timeScale = 1.0);

  double timeCache() const { return timeCache_; }
  void reset() { timeCache_ = 0.0; }
  double maximumElapsedTime() const { return maximumElapsedTime_; }
  void setMaximumElapsedTime(double seconds) { maximumElapsedTime_ = seconds; }

 private:
  double timeCache_ = 0.0;
  double maximumElapsedTime_;
};

}  // namespace odelab
