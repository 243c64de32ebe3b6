#include "GhostDraw.h"

#include <cmath>

#include "../AbstractWindow.h"
#include "../world/GhostLaw.h"
#include "EngineColours.h"

namespace odelab {

namespace {

const int CIRCLE_SEGMENTS = 32;
// Nearly opaque: the ghost is drawn over the bodies, and where an engine's
// body sits on the answer the ghost's edges must still show on it.
const std::uint8_t GHOST_ALPHA = 230;

using world::Quat;
using world::Vec3;

Vec3 rotated(const Quat& q, const Vec3& v) {
  // v + 2 w (u x v) + 2 u x (u x v), u the quaternion's vector part.
  const Vec3 u{q[1], q[2], q[3]};
  const Vec3 t{2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0])};
  return {v[0] + q[0] * t[0] + u[1] * t[2] - u[2] * t[1], v[1] + q[0] * t[1] + u[2] * t[0] - u[0] * t[2],
          v[2] + q[0] * t[2] + u[0] * t[1] - u[1] * t[0]};
}

// A geom's point at `local` (its own frame) in the world, the body at `pose`.
struct Placed {
  const world::GhostPose& pose;
  const world::Geom& geom;
  glm::vec3 operator()(const Vec3& local) const {
    const Vec3 inBody = rotated(geom.orientation, local);
    const Vec3 offset{geom.position[0] + inBody[0], geom.position[1] + inBody[1], geom.position[2] + inBody[2]};
    const Vec3 w = rotated(pose.orientation, offset);
    return {static_cast<float>(pose.position[0] + w[0]), static_cast<float>(pose.position[1] + w[1]),
            static_cast<float>(pose.position[2] + w[2])};
  }
};

// A circle of `radius` about the geom's `axis` (0, 1, 2) at `offset` along it.
void circle(VertexList& list, const Placed& at, int axis, double radius, double offset, Rgba color) {
  const double step = 2.0 * 3.14159265358979 / CIRCLE_SEGMENTS;
  auto point = [&](int i) {
    Vec3 local{0, 0, 0};
    local[static_cast<size_t>((axis + 1) % 3)] = radius * std::cos(step * i);
    local[static_cast<size_t>((axis + 2) % 3)] = radius * std::sin(step * i);
    local[static_cast<size_t>(axis)] = offset;
    return at(local);
  };
  for (int i = 0; i < CIRCLE_SEGMENTS; ++i) list.line(point(i), point(i + 1), color);
}

void outline(VertexList& list, const Placed& at, Rgba color) {
  const world::Geom& g = at.geom;
  switch (g.shape) {
    case world::ShapeKind::Box: {
      const Vec3 half{g.size[0] / 2, g.size[1] / 2, g.size[2] / 2};
      auto corner = [&](int i) {
        return at({i & 1 ? half[0] : -half[0], i & 2 ? half[1] : -half[1], i & 4 ? half[2] : -half[2]});
      };
      for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
          if (!(i & bit)) list.line(corner(i), corner(i | bit), color);
      break;
    }
    case world::ShapeKind::Sphere: {
      const double r = g.size[0];
      for (int axis = 0; axis < 3; ++axis) circle(list, at, axis, r, 0.0, color);
      // Two rings of latitude more: a small ghost still reads as a ball.
      for (const double height : {-0.6, 0.6}) circle(list, at, 1, r * 0.8, r * height, color);
      break;
    }
    case world::ShapeKind::Capsule:
    case world::ShapeKind::Cylinder: {
      const double r = g.size[0], half = g.size[1] / 2;
      for (const double end : {-half, half}) circle(list, at, 2, r, end, color);
      for (int i = 0; i < 4; ++i) {
        const double angle = 3.14159265358979 / 2 * i;
        list.line(at({r * std::cos(angle), r * std::sin(angle), -half}), at({r * std::cos(angle), r * std::sin(angle), half}),
                  color);
      }
      break;
    }
    case world::ShapeKind::Plane:
      break;  // a body has none
  }
}

}  // namespace

GhostDraw::GhostDraw(const std::string& shaderDir) : program_(shaderDir) {}

void GhostDraw::draw(const AbstractWindow& scene, const glm::mat4& viewProjection) {
  const world::GhostMotion* ghost = scene.ghost();
  if (!ghost) return;
  lines_.clear();
  const EngineColour& c = ghostColour();
  const Rgba color{c.r, c.g, c.b, GHOST_ALPHA};
  // A pure function of simulated time: a rewind or a reset puts it right at once.
  const world::GhostPose pose = ghost->at(scene.run().simulatedTime());
  for (const world::Geom& geom : ghost->shapes()) outline(lines_, Placed{pose, geom}, color);
  if (lines_.size() == 0) return;
  stream_.upload(lines_);
  program_.use(viewProjection);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);  // over the bodies: the answer shows where an engine's body covers it
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  stream_.draw(GL_LINES, 0, lines_.size());
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

std::string GhostDraw::hudLine(const world::GhostMotion& ghost) {
  return ghost.legend() + ", drawn in " + ghostColour().name + " edges";
}

}  // namespace odelab
