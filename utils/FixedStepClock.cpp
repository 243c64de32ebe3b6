#include "FixedStepClock.h"

#include <algorithm>

namespace odelab {

int FixedStepClock::advance(double elapsedSeconds, double step, double timeScale) {
  timeCache_ += std::min(std::max(elapsedSeconds, 0.0), maximumElapsedTime_) * timeScale;
  int steps = 0;
  while (timeCache_ >= step) {
    timeCache_ -= step;
    ++steps;
  }
  return steps;
}

}  // namespace odelab
