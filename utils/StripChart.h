#pragma once

#include <cstddef>
#include <deque>
#include <string>

namespace odelab {

// The live plot's data: the scene's headline measurement against simulated
// time, the latest CAPACITY samples.
class StripChart {
 public:
  static constexpr std::size_t CAPACITY = 1000;
  struct Sample {
    double time;
    double value;
  };

  void clear() {
    samples_.clear();
    changes_.clear();
  }
  // A setting changed at `time`: the plot draws a mark there.
  void markChange(double time) {
    changes_.push_back(time);
    if (changes_.size() > CAPACITY) changes_.pop_front();
  }
  const std::deque<double>& changes() const { return changes_; }
  void add(double time, double value) {
    samples_.push_back({time, value});
    if (samples_.size() > CAPACITY) samples_.pop_front();
  }
  const std::deque<Sample>& samples() const { return samples_; }
  std::string label;  // what is plotted, with its unit

 private:
  std::deque<Sample> samples_;
  std::deque<double> changes_;
};

}  // namespace odelab
