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
    const dBodyID body1 = dJointGetBody(joint, 0), body2 = dJointGetBody(joint, 1);
    marker.hasBody1 = body1 != nullptr;
    marker.hasBody2 = body2 != nullptr;
    if (body1) copy3(marker.body1, dBodyGetPosition(body1));
    if (body2) copy3(marker.body2, dBodyGetPosition(body2));
    markers.push_back(marker);
  }
  return markers;
}

}  // namespace odelab
