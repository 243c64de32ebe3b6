#include "BodyStateWatch.h"

namespace odelab {

void BodyStateWatch::refresh(const Objects& objects) const {
  bodies_.clear();
  for (const auto& object : objects)
    if (const dBodyID body = object->getBody())
      bodies_.push_back({dBodyGetPosition(body), dBodyGetLinearVel(body), dBodyGetAngularVel(body)});
  seen_ = AbstractObject::bodyChanges();
}

}  // namespace odelab
