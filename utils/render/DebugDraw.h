#pragma once

#include <glm/glm.hpp>
#include <string>

#include "../AbstractWindow.h"
#include "Lines.h"

namespace odelab {

// The debug drawing over the lit scene, each part toggled by a view key:
// contact points and normals (C), joint anchors and hinge axes (J),
// axis-aligned bounding boxes (X), and the mouse drag's spring. All of it is
// gathered into one reused vertex list and uploaded into one dynamic buffer
// per frame: boxes are depth-tested; markers, which often sit inside or
// under bodies, are drawn over everything.
class DebugDraw {
 public:
  explicit DebugDraw(const std::string& shaderDir);

  // dragFrom / dragTo: the drag's line, when `dragging`.
  void draw(const AbstractWindow& scene, const glm::mat4& viewProjection, bool dragging, const glm::vec3& dragFrom,
            const glm::vec3& dragTo);

 private:
  void addBoxes(const AbstractWindow& scene);
  void addContacts(const AbstractWindow& scene, const glm::vec3& eye);
  void addJoints(const AbstractWindow& scene, const glm::vec3& eye);
  void addBallLinks(const AbstractWindow& scene);

  LineProgram program_;
  VertexStream stream_;
  VertexList lines_;     // depth-tested lines
  VertexList overlay_;   // lines over everything
  VertexList points_;    // points over everything
  VertexList all_;       // the three above, as uploaded
};

}  // namespace odelab
