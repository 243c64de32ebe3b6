#include "Timeline.h"

#include <algorithm>

namespace odelab {

void Timeline::clear() {
  events_.clear();
  snapshots_.clear();
  cursor_ = 0;
  horizon_ = 0;
}

void Timeline::record(const TimelineEvent& event) {
  // Drop the old future: events after this step, and those at this step that
  // were not yet applied.
  events_.erase(std::remove_if(events_.begin() + static_cast<long>(cursor_), events_.end(),
                               [&](const TimelineEvent& e) { return e.step >= event.step; }),
                events_.end());
  while (!snapshots_.empty() && snapshots_.back() > event.step) snapshots_.pop_back();
  horizon_ = event.step;
  events_.push_back(event);
  cursor_ = events_.size();  // recorded inputs are applied by the caller at once
}

void Timeline::markSnapshot(long long step) {
  if (!snapshots_.empty() && snapshots_.back() >= step) return;
  snapshots_.push_back(step);
  while (snapshots_.size() > SNAPSHOT_CAPACITY) snapshots_.pop_front();
}

long long Timeline::previousSnapshot(long long step) const {
  for (auto it = snapshots_.rbegin(); it != snapshots_.rend(); ++it)
    if (*it < step) return *it;
  return -1;
}

long long Timeline::nextSnapshot(long long step) const {
  for (long long mark : snapshots_)
    if (mark > step && mark <= horizon_) return mark;
  // Past the last mark, the furthest step reached (where a run paused
  // between marks was) is the way back.
  return step < horizon_ ? horizon_ : -1;
}

}  // namespace odelab
