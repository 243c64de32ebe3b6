#include "DebugDraw.h"

#include <cmath>

namespace odelab {

namespace {

// Markers keep their size on the screen: their length is this fraction of
// their distance from the camera (0.05 is about 30 pixels in a 720-pixel
// window with the 60-degree field of view).
const float NORMAL_LENGTH = 0.04f;
const float CROSS_SIZE = 0.025f;
const float AXIS_LENGTH = 0.12f;
const float POINT_PIXELS = 6.0f;

const Rgba BOX_COLOR{90, 235, 120, 255};
const Rgba BOX_DISABLED_COLOR{150, 150, 150, 255};
const Rgba CONTACT_COLOR{255, 40, 40, 255};
const Rgba NORMAL_COLOR{255, 225, 40, 255};
const Rgba ANCHOR_COLOR{40, 230, 255, 255};
const Rgba ANCHOR2_COLOR{255, 60, 230, 255};
const Rgba SEPARATION_COLOR{255, 255, 255, 255};
const Rgba LINK_COLOR{255, 215, 90, 255};  // a ball joint's link
const Rgba AXIS_COLOR{255, 150, 30, 255};
const Rgba DRAG_COLOR{255, 255, 255, 255};

glm::vec3 vec(const float v[3]) { return {v[0], v[1], v[2]}; }

float screenScale(const glm::vec3& at, const glm::vec3& eye) { return std::max(glm::length(at - eye), 0.05f); }

void cross(VertexList& list, const glm::vec3& p, float size, Rgba color) {
  list.line(p - glm::vec3(size, 0, 0), p + glm::vec3(size, 0, 0), color);
  list.line(p - glm::vec3(0, size, 0), p + glm::vec3(0, size, 0), color);
  list.line(p - glm::vec3(0, 0, size), p + glm::vec3(0, 0, size), color);
}

void wireBox(VertexList& list, const dReal aabb[6], Rgba color) {
  // aabb: minX, maxX, minY, maxY, minZ, maxZ.
  auto corner = [&](int i) {
    return glm::vec3(aabb[(i & 1) ? 1 : 0], aabb[(i & 2) ? 3 : 2], aabb[(i & 4) ? 5 : 4]);
  };
  // The 12 edges join corners that differ in one bit.
  for (int i = 0; i < 8; ++i)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(i & bit)) list.line(corner(i), corner(i | bit), color);
}

}  // namespace

DebugDraw::DebugDraw(const std::string& shaderDir) : program_(shaderDir) {}

void DebugDraw::addBoxes(const AbstractWindow& scene) {
  for (const auto& object : scene.run().objects()) {
    if (!object->visible) continue;
    const dGeomID geom = object->getGeom();
    if (dGeomGetClass(geom) == dPlaneClass) continue;  // infinite
    dReal aabb[6];
    dGeomGetAABB(geom, aabb);
    bool finite = true;
    for (dReal v : aabb) finite = finite && std::isfinite(v);
    if (finite) wireBox(lines_, aabb, object->isEnabled() || object->isFixed() ? BOX_COLOR : BOX_DISABLED_COLOR);
  }
}

void DebugDraw::addContacts(const AbstractWindow& scene, const glm::vec3& eye) {
  for (const ContactMarker& contact : scene.session().contactMarkers()) {
    const glm::vec3 p = vec(contact.position);
    points_.point(p, CONTACT_COLOR);
    overlay_.line(p, p + vec(contact.normal) * (NORMAL_LENGTH * screenScale(p, eye)), NORMAL_COLOR);
  }
}

void DebugDraw::addJoints(const AbstractWindow& scene, const glm::vec3& eye) {
  for (const JointMarker& joint : scene.run().jointMarkers()) {
    const glm::vec3 a = vec(joint.anchor), b = vec(joint.anchor2);
    const float scale = screenScale(a, eye);
    cross(overlay_, a, CROSS_SIZE * scale, ANCHOR_COLOR);
    // The two anchors part when the joint is not held exactly (ERP, CFM).
    if (glm::length(b - a) > 1e-6f * scale) {
      cross(overlay_, b, CROSS_SIZE * scale, ANCHOR2_COLOR);
      overlay_.line(a, b, SEPARATION_COLOR);
    }
    if (joint.hasAxis) {
      const glm::vec3 axis = vec(joint.axis) * (AXIS_LENGTH * scale);
      overlay_.line(a - axis, a + axis, AXIS_COLOR);
    }
  }
}

// A ball joint has no visible part: its link, from each body's centre to
// its anchor, is always drawn (test6, test7), over the bodies.
void DebugDraw::addBallLinks(const AbstractWindow& scene) {
  for (const JointMarker& joint : scene.run().jointMarkers()) {
    if (joint.hasAxis) continue;
    if (joint.hasBody1) overlay_.line(vec(joint.body1), vec(joint.anchor), LINK_COLOR);
    if (joint.hasBody2) overlay_.line(vec(joint.body2), vec(joint.anchor2), LINK_COLOR);
    points_.point(vec(joint.anchor), LINK_COLOR);
  }
}

void DebugDraw::draw(const AbstractWindow& scene, const glm::mat4& viewProjection, bool dragging,
                     const glm::vec3& dragFrom, const glm::vec3& dragTo) {
  const ViewFlags& flags = scene.session().viewFlags();
  lines_.clear();
  overlay_.clear();
  points_.clear();
  addBallLinks(scene);
  if (!flags.boxes && !flags.contacts && !flags.joints && !dragging && overlay_.size() == 0) return;
  const glm::vec3 eye = scene.camera().position();
  if (flags.boxes) addBoxes(scene);
  if (flags.contacts) addContacts(scene, eye);
  if (flags.joints) addJoints(scene, eye);
  if (dragging) {
    overlay_.line(dragFrom, dragTo, DRAG_COLOR);
    points_.point(dragTo, DRAG_COLOR);
    points_.point(dragFrom, DRAG_COLOR);
  }

  all_.clear();
  all_.append(lines_);
  all_.append(overlay_);
  all_.append(points_);
  if (all_.size() == 0) return;
  stream_.upload(all_);
  program_.use(viewProjection);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  // One-pixel lines need no antialiasing, and a software renderer draws
  // multisampled lines at several times the cost (test5's 1200 box edges:
  // about 9 ms against 3 ms a frame with Mesa's llvmpipe).
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_DEPTH_TEST);
  stream_.draw(GL_LINES, 0, lines_.size());
  glDisable(GL_DEPTH_TEST);
  stream_.draw(GL_LINES, lines_.size(), overlay_.size());
  glPointSize(POINT_PIXELS);
  stream_.draw(GL_POINTS, lines_.size() + overlay_.size(), points_.size());
  glPointSize(1.0f);
  glEnable(GL_MULTISAMPLE);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace odelab
