#pragma once

#include <memory>
#include <vector>

#include "AbstractObject.h"

namespace odelab {

// What the debug drawing shows, gathered on the physics side so the renderer
// only draws: contact points with normals (recorded in the near callback
// while shown) and the anchors and axes of every non-contact joint.
struct ContactMarker {
  float position[3];
  float normal[3];
  float depth;
};

struct JointMarker {
  float anchor[3];   // on the first body
  float anchor2[3];  // on the second body (equal to anchor when the joint holds)
  float axis[3];
  bool hasAxis;      // hinges have an axis; ball joints do not
  // The centres of the joined bodies (a joint to the static world has one).
  float body1[3], body2[3];
  bool hasBody1, hasBody2;
};

std::vector<JointMarker> collectJointMarkers(const std::vector<std::unique_ptr<AbstractObject>>& objects);

}  // namespace odelab
