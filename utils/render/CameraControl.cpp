#include "CameraControl.h"

#include <algorithm>
#include <cmath>

namespace odelab {

namespace {

const float ORBIT_DEGREES_PER_PIXEL = 0.3f;
// A notch brings the eye this much nearer the target (its inverse: further).
const float ZOOM_PER_NOTCH = 0.88f;
// One W/S/A/D press: the distance held keys fly in an eighth of a second.
const float NUDGE_METRES = 1.0f;

}  // namespace

bool CameraControl::handleKey(const SDL_KeyboardEvent& key, AbstractWindow& scene) {
  Camera& camera = scene.camera();
  const bool shift = (key.keysym.mod & KMOD_SHIFT) != 0;
  switch (key.keysym.sym) {
    case SDLK_HOME:
      followed_ = -1;
      if (shift)
        frameScene(scene);
      else
        camera.goHome();
      return true;
    // Held keys fly the camera from the keyboard's state; the press itself
    // moves it one nudge, so a tap (or scripted input, which the keyboard
    // state never sees) moves it too.
    case SDLK_w:
      if (!key.repeat) camera.move(NUDGE_METRES, 0.0f);
      return true;
    case SDLK_s:
      if (!key.repeat) camera.move(-NUDGE_METRES, 0.0f);
      return true;
    case SDLK_a:
      if (!key.repeat) camera.move(0.0f, -NUDGE_METRES);
      return true;
    case SDLK_d:
      if (!key.repeat) camera.move(0.0f, NUDGE_METRES);
      return true;
    default:
      return false;
  }
}

bool CameraControl::pressButton(const SDL_MouseButtonEvent& button) {
  if (mode_ != Mode::None) return false;
  const bool shift = (SDL_GetModState() & KMOD_SHIFT) != 0;
  const bool leftOrRight = button.button == SDL_BUTTON_LEFT || button.button == SDL_BUTTON_RIGHT;
  if (button.button == SDL_BUTTON_MIDDLE || (shift && leftOrRight))
    mode_ = Mode::Pan;
  else if (leftOrRight)
    mode_ = Mode::Orbit;
  else
    return false;
  button_ = button.button;
  return true;
}

bool CameraControl::releaseButton(const SDL_MouseButtonEvent& button) {
  if (mode_ == Mode::None || button.button != button_) return false;
  mode_ = Mode::None;
  return true;
}

bool CameraControl::moveMouse(const SDL_MouseMotionEvent& motion, Camera& camera, int viewHeight) {
  if (mode_ == Mode::None) return false;
  const float dx = static_cast<float>(motion.xrel), dy = static_cast<float>(motion.yrel);
  if (mode_ == Mode::Orbit) {
    // Dragging down raises the eye (the scene tips toward the viewer).
    camera.orbit(-dx * ORBIT_DEGREES_PER_PIXEL, -dy * ORBIT_DEGREES_PER_PIXEL);
  } else {
    // The target's plane moves with the cursor: a pixel there is this many metres.
    const float metresPerPixel = 2.0f * camera.distance() *
                                 std::tan(glm::radians(camera.fieldOfViewDegrees()) * 0.5f) /
                                 static_cast<float>(std::max(1, viewHeight));
    camera.pan(-dx * metresPerPixel, dy * metresPerPixel);
  }
  return true;
}

void CameraControl::wheel(const SDL_MouseWheelEvent& wheel, Camera& camera) {
  // Away from the user zooms in; a flipped ("natural") wheel reports the opposite.
  const int notches = wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -wheel.y : wheel.y;
  if (notches != 0) camera.zoom(std::pow(ZOOM_PER_NOTCH, static_cast<float>(notches)));
}

namespace {
glm::vec3 positionOf(const AbstractObject& object) {
  const dReal* p = object.getPosition();
  return {p[0], p[1], p[2]};
}
}  // namespace

void CameraControl::follow(int index, const AbstractWindow& scene) {
  const auto& objects = scene.run().objects();
  followed_ = index >= 0 && index < static_cast<int>(objects.size()) ? index : -1;
  if (followed_ < 0) return;
  followedObject_ = objects[static_cast<size_t>(index)].get();
  followedAt_ = positionOf(*followedObject_);
}

void CameraControl::keepFollowing(AbstractWindow& scene) {
  if (followed_ < 0) return;
  const auto& objects = scene.run().objects();
  // A reset or a rewind builds new objects: the one followed is gone.
  if (followed_ >= static_cast<int>(objects.size()) || objects[static_cast<size_t>(followed_)].get() != followedObject_) {
    followed_ = -1;
    return;
  }
  const glm::vec3 now = positionOf(*followedObject_);
  if (!std::isfinite(now.x) || !std::isfinite(now.y) || !std::isfinite(now.z)) return;
  scene.camera().shift(now - followedAt_);
  followedAt_ = now;
}

void frameScene(AbstractWindow& scene) {
  glm::vec3 low(1e30f), high(-1e30f);
  bool any = false;
  for (const auto& object : scene.run().objects()) {
    if (object->shape() == Shape::Plane || !object->getGeom()) continue;
    dReal box[6];
    dGeomGetAABB(object->getGeom(), box);
    if (!std::isfinite(box[0]) || !std::isfinite(box[1]) || std::abs(box[1]) > 1e4) continue;
    low = glm::min(low, glm::vec3(box[0], box[2], box[4]));
    high = glm::max(high, glm::vec3(box[1], box[3], box[5]));
    any = true;
  }
  if (!any) {
    scene.camera().goHome();
    return;
  }
  scene.camera().frame((low + high) * 0.5f, 0.5f * glm::length(high - low));
}

}  // namespace odelab
