#pragma once

#include <SDL2/SDL_keycode.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace odelab {

// An input that changes the simulation, stamped with the step it came before.
struct TimelineEvent {
  // Key: a recorded key press. Drag / Release: the mouse spring.
  // Knob: a knob set from the panel (index: its place in the scene's knobs).
  enum class Kind { Key, Drag, Release, Knob };
  long long step = 0;
  Kind kind = Kind::Key;
  SDL_Keycode key = 0;
  bool shift = false;
  int objectIndex = -1;          // Drag: index into the scene's objects
  double target[3] = {0, 0, 0};  // Drag: where the spring pulls (world)
  double grab[3] = {0, 0, 0};    // Drag: the grabbed point in the body's frame
  int index = -1;                // Knob: which one
  double value = 0.0;            // Knob: the new value
};

// The inputs of one run since its last reset, in order, and snapshot marks:
// the steps to which ',' and '.' move. A state is rebuilt by resetting the
// scene and replaying the inputs up to the wanted step, which reproduces it
// bit for bit (ODE keeps state no API can restore, such as auto-disable
// counters, so copying body states back would not).
class Timeline {
 public:
  static constexpr std::size_t SNAPSHOT_CAPACITY = 240;

  void clear();
  // Adds an input at event.step. Inputs recorded after a rewind replace the
  // old future: later events and snapshot marks are dropped.
  void record(const TimelineEvent& event);
  const std::vector<TimelineEvent>& events() const { return events_; }

  // Playback cursor: the events due before step `step` runs.
  void rewindCursor() { cursor_ = 0; }
  template <class Apply>
  void applyDue(long long step, Apply apply) {
    while (cursor_ < events_.size() && events_[cursor_].step <= step) apply(events_[cursor_++]);
  }

  void markSnapshot(long long step);
  // The last mark before `step`, or -1; the first mark after `step` that is
  // within the recorded horizon, else the horizon when `step` is before it,
  // else -1.
  long long previousSnapshot(long long step) const;
  long long nextSnapshot(long long step) const;
  // The furthest step this branch of the run has reached.
  long long horizon() const { return horizon_; }
  void extendHorizon(long long step) {
    if (step > horizon_) horizon_ = step;
  }
  std::size_t snapshotCount() const { return snapshots_.size(); }

 private:
  std::vector<TimelineEvent> events_;
  std::size_t cursor_ = 0;
  std::deque<long long> snapshots_;
  long long horizon_ = 0;
};

}  // namespace odelab
