#include "Rewind.h"

namespace odelab {

void Rewind::begin(const RunStart& start) {
  timeline_.clear();
  start_ = start;
  for (auto& kept : kept_) kept.save();
}

const RunStart& Rewind::restore() {
  for (auto& kept : kept_) kept.restore();
  timeline_.rewindCursor();
  return start_;
}

void Rewind::afterStep(double simulatedTime, long long steps) {
  timeline_.extendHorizon(steps);
  if (simulatedTime >= nextSnapshot_) {
    timeline_.markSnapshot(steps);
    nextSnapshot_ += SNAPSHOT_INTERVAL;
  }
}

void Rewind::record(const TimelineEvent& event) {
  if (!replaying_) timeline_.record(event);
}

}  // namespace odelab
