#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "SpaceKind.h"
#include "Timeline.h"
#include "WorldSettings.h"

namespace odelab {

// What a run starts from, and so what a replay restores before it replays
// the recorded inputs: the world settings, the collision space, the F2
// increment, and every scene value kept with keep().
struct RunStart {
  WorldSettings settings;
  SpaceKind space = SpaceKind::Simple;
  F2Increment increment;
};

// Rewind by replay: the run's start, its timeline of recorded inputs and
// its snapshot marks. A state is rebuilt by building the scene again from
// the start and replaying inputs up to the wanted step (see Timeline).
class Rewind {
 public:
  // Snapshot marks fall every quarter second of simulated time.
  static constexpr double SNAPSHOT_INTERVAL = 0.25;

  // A scene value that keys or the panel change and that survives R (a
  // launch velocity, a friction coefficient): a replay puts back its value
  // at the start of the run.
  template <class T>
  void keep(T& value) {
    auto saved = std::make_shared<T>(value);
    kept_.push_back({[&value, saved] { *saved = value; }, [&value, saved] { value = *saved; }});
  }

  // The same for a value read and written through functions (a choice
  // knob: test0's spawn shapes, test5's space, the solver).
  void keepThrough(std::function<double()> get, std::function<void(double)> set) {
    auto saved = std::make_shared<double>(get());
    kept_.push_back({[get, saved] { *saved = get(); }, [set, saved] { set(*saved); }});
  }

  // A new run (the first, or after R): the timeline starts empty.
  void begin(const RunStart& start);
  // Before a replay: the start's values, kept values put back, cursor at 0.
  const RunStart& restore();
  // A new world was built: snapshot marks start again.
  void worldRebuilt() { nextSnapshot_ = SNAPSHOT_INTERVAL; }
  // After each step: marks a snapshot every SNAPSHOT_INTERVAL.
  void afterStep(double simulatedTime, long long steps);
  // Adds an input, unless it is being replayed.
  void record(const TimelineEvent& event);

  Timeline& timeline() { return timeline_; }
  const Timeline& timeline() const { return timeline_; }
  bool replaying() const { return replaying_; }
  void setReplaying(bool replaying) { replaying_ = replaying; }
  // Counts runs begun by R (not replays): a key that reset the scene is not recorded.
  long long epoch() const { return epoch_; }
  void newEpoch() { ++epoch_; }

 private:
  struct Kept {
    std::function<void()> save, restore;
  };
  RunStart start_;
  std::vector<Kept> kept_;
  Timeline timeline_;
  bool replaying_ = false;
  long long epoch_ = 0;
  double nextSnapshot_ = SNAPSHOT_INTERVAL;
};

}  // namespace odelab
