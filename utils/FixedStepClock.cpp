#include "FixedStepClock.h"

#include <algorithm>

namespace odelab {

int FixedStepClock::advance(double elapsedSeconds, double step) {
  timeCache_ += std::min(std::max(elapsedSeconds, 0.0), MAXIMUM_ELAPSED_TIME);
  int steps = 0;
  while (timeCache_ >= step) {
    timeCache_ -= step;
    ++steps;
  }
  return steps;
}

}  // namespace odelab
