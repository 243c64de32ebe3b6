#pragma once

#include <memory>
#include <vector>

#include "AbstractObject.h"
#include "DragSpring.h"
#include "Timeline.h"

namespace odelab {

// The mouse-drag spring's state: which object is held, the grabbed point in
// its body's frame, and where the spring pulls. Every change is a timeline
// event, so a replay drags exactly as the user did.
class MouseDrag {
 public:
  using Objects = std::vector<std::unique_ptr<AbstractObject>>;

  // The events that start, move and end a drag at `step`: each fills
  // `event` and returns true, or returns false when there is nothing to do
  // (no body hit, no drag in progress).
  static bool beginEvent(const Objects& objects, const PickHit& hit, const double target[3], long long step,
                         TimelineEvent& event);
  bool moveEvent(const double target[3], long long step, TimelineEvent& event) const;
  bool endEvent(long long step, TimelineEvent& event) const;
  // Applies a Drag or Release event (live or replayed).
  void apply(const TimelineEvent& event, int objectCount);
  // Before a step: the spring pulls the held body. Returns whether it did,
  // with the force and the world point where it acts.
  bool pull(const Objects& objects, double gravity, double force[3], double point[3]) const;
  // The grabbed point in the world frame, of the object at `index` (held now
  // or a moment ago); false when it has no body.
  bool grabbedPoint(const Objects& objects, int index, double point[3]) const;
  // The gap the spring still has to close, in metres (0 when not dragging).
  double gap(const Objects& objects) const;

  bool active() const { return index_ >= 0; }
  int index() const { return index_; }
  const double* target() const { return target_; }
  void release() { index_ = -1; }
  // After objects were removed: follows the held object to its new index.
  void follow(const Objects& objects, const AbstractObject* held);

 private:
  int index_ = -1;
  double grab_[3] = {0, 0, 0};
  double target_[3] = {0, 0, 0};
};

}  // namespace odelab
