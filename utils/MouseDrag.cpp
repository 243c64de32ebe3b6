#include "MouseDrag.h"

#include <algorithm>

namespace odelab {

bool MouseDrag::beginEvent(const Objects& objects, const PickHit& hit, const double target[3], long long step,
                           TimelineEvent& event) {
  if (hit.objectIndex < 0 || hit.objectIndex >= static_cast<int>(objects.size())) return false;
  const dBodyID body = objects[hit.objectIndex]->getBody();
  if (!body) return false;  // a static object: nothing to pull
  dVector3 local;
  dBodyGetPosRelPoint(body, hit.point[0], hit.point[1], hit.point[2], local);
  event = TimelineEvent{};
  event.step = step;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = hit.objectIndex;
  std::copy(local, local + 3, event.grab);
  std::copy(target, target + 3, event.target);
  return true;
}

bool MouseDrag::moveEvent(const double target[3], long long step, TimelineEvent& event) const {
  if (index_ < 0) return false;
  event = TimelineEvent{};
  event.step = step;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = index_;
  std::copy(grab_, grab_ + 3, event.grab);
  std::copy(target, target + 3, event.target);
  return true;
}

bool MouseDrag::endEvent(long long step, TimelineEvent& event) const {
  if (index_ < 0) return false;
  event = TimelineEvent{};
  event.step = step;
  event.kind = TimelineEvent::Kind::Release;
  return true;
}

void MouseDrag::apply(const TimelineEvent& event, int objectCount) {
  if (event.kind == TimelineEvent::Kind::Release) {
    index_ = -1;
    return;
  }
  index_ = event.objectIndex < objectCount ? event.objectIndex : -1;
  std::copy(event.grab, event.grab + 3, grab_);
  std::copy(event.target, event.target + 3, target_);
}

bool MouseDrag::pull(const Objects& objects, double gravity, double force[3], double point[3]) const {
  if (index_ < 0) return false;
  const dBodyID body = objects[index_]->getBody();
  if (!body) return false;
  DragSpring::apply(body, grab_, target_, gravity, force, point);
  return true;
}

bool MouseDrag::grabbedPoint(const Objects& objects, int index, double point[3]) const {
  if (index < 0 || index >= static_cast<int>(objects.size())) return false;
  const dBodyID body = objects[index]->getBody();
  if (!body) return false;
  DragSpring::grabbedPoint(body, grab_, point);
  return true;
}

double MouseDrag::gap(const Objects& objects) const {
  if (index_ < 0) return 0.0;
  const dBodyID body = objects[index_]->getBody();
  return body ? DragSpring::distance(body, grab_, target_) : 0.0;
}

void MouseDrag::follow(const Objects& objects, const AbstractObject* held) {
  index_ = -1;
  for (size_t i = 0; held && i < objects.size(); ++i)
    if (objects[i].get() == held) index_ = static_cast<int>(i);
}

}  // namespace odelab
