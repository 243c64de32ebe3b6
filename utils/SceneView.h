#pragma once

namespace odelab {

// What the debug drawing and overlays show; toggled by view keys.
struct ViewFlags {
  bool contacts = false;   // C: contact points and normals
  bool joints = false;     // J: joint anchors and axes
  bool boxes = false;      // X: axis-aligned bounding boxes
  bool wireframe = false;  // V: wireframe
  bool plot = false;       // L: live plot of the scene's measurement
  bool help = false;       // H: the key list
};

// A sphere around what the scene shows, used to fit the shadow map.
struct SceneBounds {
  double centre[3];
  double radius;
};

}  // namespace odelab
