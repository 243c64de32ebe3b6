#pragma once

#include <deque>

namespace odelab {

// The mean cost per step over the last `windowSeconds` of simulated time (a
// wall or CPU time per step), summed incrementally: O(1) per step.
class StepCostWindow {
 public:
  // `windowSeconds`: how much simulated time the mean covers.
  explicit StepCostWindow(double windowSeconds) : window_(windowSeconds) {}
  void clear() {
    samples_.clear();
    sum_ = 0.0;
  }
  void add(double simulatedTime, double wallSeconds) {
    samples_.push_back({simulatedTime, wallSeconds});
    sum_ += wallSeconds;
    while (!samples_.empty() && samples_.front().time <= simulatedTime - window_) {
      sum_ -= samples_.front().wall;
      samples_.pop_front();
    }
  }
  double meanMilliseconds() const { return samples_.empty() ? 0.0 : 1000.0 * sum_ / samples_.size(); }

 private:
  struct Sample {
    double time, wall;
  };
  double window_;
  std::deque<Sample> samples_;
  double sum_ = 0.0;
};

}  // namespace odelab
