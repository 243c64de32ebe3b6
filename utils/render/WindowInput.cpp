#include "WindowInput.h"

namespace odelab {

namespace {

const float METRES_PER_SECOND = 8.0f;

}  // namespace

void WindowInput::ray(const AbstractWindow& scene, int x, int y, const ViewRect& view, glm::vec3& origin,
                      glm::vec3& direction) const {
  const float w = static_cast<float>(view.width > 0 ? view.width : 1);
  const float h = static_cast<float>(view.height > 0 ? view.height : 1);
  // The centre of the pixel, in normalised device coordinates (y up).
  const float ndcX = (static_cast<float>(x - view.x) + 0.5f) / w * 2.0f - 1.0f;
  const float ndcY = 1.0f - (static_cast<float>(y - view.y) + 0.5f) / h * 2.0f;
  scene.camera().rayThrough(ndcX, ndcY, w / h, origin, direction);
}

bool WindowInput::pressLeft(const SDL_MouseButtonEvent& button, AbstractWindow& scene, const ViewRect& view) {
  glm::vec3 origin, direction;
  ray(scene, button.x, button.y, view, origin, direction);
  const double o[3] = {origin.x, origin.y, origin.z};
  const double d[3] = {direction.x, direction.y, direction.z};
  const PickHit hit = scene.run().pickAt(o, d);
  if (hit.objectIndex < 0) {  // nothing there: the camera's (a double click stops following)
    if (button.clicks >= 2) camera_.follow(-1, scene);
    return false;
  }
  if (button.clicks >= 2) camera_.follow(hit.objectIndex, scene);
  scene.beginDrag(hit, hit.point);
  if (!scene.session().dragging()) return false;  // a static object: nothing to pull
  held_ = true;
  grabDistance_ = hit.distance;
  grabbed_ = scene.draggedObject();
  dBodyGetPosRelPoint(grabbed_->getBody(), hit.point[0], hit.point[1], hit.point[2], grabLocal_);
  return true;
}

bool WindowInput::handleEvent(const SDL_Event& event, AbstractWindow& scene, const ViewRect& view) {
  switch (event.type) {
    case SDL_QUIT:
      scene.session().requestQuit();
      break;
    case SDL_KEYDOWN:
      if (event.key.keysym.sym == SDLK_ESCAPE) scene.session().requestQuit();
      if (camera_.handleKey(event.key, scene)) break;
      // Auto-repeat would toggle switches and step settings at the repeat
      // rate; one press is one action.
      if (event.key.keysym.sym != SDLK_ESCAPE && !event.key.repeat)
        scene.handleKey(event.key.keysym.sym, (event.key.keysym.mod & KMOD_SHIFT) != 0);
      break;
    case SDL_MOUSEBUTTONDOWN:
      // The left button on a body drags it; any other press is the camera's.
      if (held_ || camera_.active()) break;
      if (event.button.button == SDL_BUTTON_LEFT && !(SDL_GetModState() & KMOD_SHIFT) &&
          pressLeft(event.button, scene, view))
        break;
      camera_.pressButton(event.button);
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.button == SDL_BUTTON_LEFT && held_) {
        held_ = false;
        grabbed_ = nullptr;
        scene.endDrag();
      }
      camera_.releaseButton(event.button);
      break;
    case SDL_MOUSEMOTION:
      if (held_ && (event.motion.state & SDL_BUTTON_LMASK)) {
        // Keep the grab distance along the new ray: the target follows the
        // cursor across the screen at the depth where the body was grabbed.
        glm::vec3 origin, direction;
        ray(scene, event.motion.x, event.motion.y, view, origin, direction);
        const glm::vec3 target = origin + direction * static_cast<float>(grabDistance_);
        const double t[3] = {target.x, target.y, target.z};
        scene.moveDrag(t);
      } else {
        camera_.moveMouse(event.motion, scene.camera(), view.height);
      }
      break;
    case SDL_MOUSEWHEEL:
      camera_.wheel(event.wheel, scene.camera());
      break;
    case SDL_WINDOWEVENT:
      return event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED;
    default:
      break;
  }
  return false;
}

bool WindowInput::dragLine(const AbstractWindow& scene, glm::vec3& grabbed, glm::vec3& target) const {
  const AbstractObject* object = scene.draggedObject();
  if (!object || !object->getBody()) return false;
  dVector3 p;
  // The point grabbed here; a drag the timeline replayed (after a rewind)
  // is drawn from the body's centre.
  if (object == grabbed_)
    dBodyGetRelPointPos(object->getBody(), grabLocal_[0], grabLocal_[1], grabLocal_[2], p);
  else
    for (int k = 0; k < 3; ++k) p[k] = dBodyGetPosition(object->getBody())[k];
  const double* t = scene.session().dragTarget();
  grabbed = glm::vec3(p[0], p[1], p[2]);
  target = glm::vec3(t[0], t[1], t[2]);
  return true;
}

void moveCamera(AbstractWindow& scene, double frameSeconds) {
  const Uint8* keys = SDL_GetKeyboardState(nullptr);
  const float forward = static_cast<float>(keys[SDL_SCANCODE_W] - keys[SDL_SCANCODE_S]);
  const float right = static_cast<float>(keys[SDL_SCANCODE_D] - keys[SDL_SCANCODE_A]);
  if (forward == 0.0f && right == 0.0f) return;
  const float step = METRES_PER_SECOND * static_cast<float>(frameSeconds);
  scene.camera().move(forward * step, right * step);
}

bool cameraKeysHeld() {
  const Uint8* keys = SDL_GetKeyboardState(nullptr);
  return keys[SDL_SCANCODE_W] || keys[SDL_SCANCODE_S] || keys[SDL_SCANCODE_A] || keys[SDL_SCANCODE_D];
}

void syncMouseLook(const AbstractWindow& scene) {
  const SDL_bool wanted = scene.session().mouseLook() ? SDL_TRUE : SDL_FALSE;
  // May fail where relative mode is unsupported; the camera still turns by motion.
  if (SDL_GetRelativeMouseMode() != wanted) SDL_SetRelativeMouseMode(wanted);
}

}  // namespace odelab
