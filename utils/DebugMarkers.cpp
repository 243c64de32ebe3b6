#include "DebugMarkers.h"

#include <set>

namespace odelab {

namespace {
void copy3(float* to, const dReal* from) {
  for (int k = 0; k < 3; ++k) to[k] = static_cast<float>(from[k]);
}
}  // namespace

std::vector<JointMarker> collectJointMarkers(const std::vector<std::unique_ptr<AbstractObject>>& objects) {
  std::set<dJointID> joints;
  for (const auto& object : objects) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    for (int i = 0; i < dBodyGetNumJoints(body); ++i) {
      dJointID joint = dBodyGetJoint(body, i);
      if (dJointGetType(joint) != dJointTypeContact) joints.insert(joint);
    }
  }
  std::vector<JointMarker> markers;
  for (dJointID joint : joints) {
    JointMarker marker{};
    dVector3 a, b, axis;
    switch (dJointGetType(joint)) {
      case dJointTypeBall:
        dJointGetBallAnchor(joint, a);
        dJointGetBallAnchor2(joint, b);
        marker.hasAxis = false;
        break;
      case dJointTypeHinge:
        dJointGetHingeAnchor(joint, a);
        dJointGetHingeAnchor2(joint, b);
        dJointGetHingeAxis(joint, axis);
        copy3(marker.axis, axis);
        marker.hasAxis = true;
        break;
      default:
        continue;  // the scenes use ball and hinge joints only
    }
    copy3(marker.anchor, a);
    copy3(marker.anchor2, b);
    markers.push_back(marker);
  }
  return markers;
}

}  // namespace odelab
