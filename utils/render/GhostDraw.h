#pragma once

#include <string>

#include <glm/glm.hpp>

#include "Lines.h"

namespace odelab {

class AbstractWindow;
namespace world {
class GhostMotion;
}

// A world file's ghost (world/GhostLaw.h) in the window: the body's shape,
// edges only, in ghostColour() (EngineColours.h), at the pose its analytic
// law gives for the scene's simulated time, over every view, so each
// engine's body is seen against the answer. The pose is computed on the
// physics side; this only draws it.
class GhostDraw {
 public:
  explicit GhostDraw(const std::string& shaderDir);
  // `scene`'s ghost, if it states one; the viewport is the view's.
  void draw(const AbstractWindow& scene, const glm::mat4& viewProjection);
  // The HUD's line saying what the ghost is and how it is drawn.
  static std::string hudLine(const world::GhostMotion& ghost);

 private:
  LineProgram program_;
  VertexStream stream_;
  VertexList lines_;
};

}  // namespace odelab
