#include "WindowInput.h"

#include <algorithm>
#include <cstdlib>


namespace odelab {

namespace {

const float METRES_PER_SECOND = 8.0f;
// A press on a body becomes a drag once the cursor moves this far (window
// pixels, either way): a click is not a drag.
const int LEAST_DRAG_PIXELS = 4;

// Shown (on the HUD, for a few seconds) by an Esc that would lose changed
// settings; a second Esc while it shows quits.
const char* const QUIT_PROMPT =
    "settings changed since the start: Esc again quits; the panel's \"Copy as command line\" keeps them";

// What a person tunes in a session: every knob.
std::vector<double> tuningOf(const AbstractWindow& scene) {
  std::vector<double> values;
  for (const Knob& knob : scene.tuning().knobs()) values.push_back(knob.get());
  return values;
}

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
  // A double click on a body follows it and pulls nothing.
  if (button.clicks >= 2) {
    camera_.follow(hit.objectIndex, scene);
    return true;
  }
  const dBodyID body = scene.run().objects()[hit.objectIndex]->getBody();
  if (!body) return false;  // a static object: nothing to pull
  // The drag begins when the cursor moves (moveLeft): a click, the first
  // of a double click too, neither pulls the body nor enters the timeline.
  held_ = true;
  pulling_ = false;
  pressed_ = hit;
  pressX_ = button.x;
  pressY_ = button.y;
  grabDistance_ = hit.distance;
  dBodyGetPosRelPoint(body, hit.point[0], hit.point[1], hit.point[2], grabLocal_);
  return true;
}

void WindowInput::moveLeft(const SDL_MouseMotionEvent& motion, AbstractWindow& scene, const ViewRect& view) {
  if (!pulling_) {
    if (std::abs(motion.x - pressX_) < LEAST_DRAG_PIXELS && std::abs(motion.y - pressY_) < LEAST_DRAG_PIXELS) return;
    // The point grabbed at the press, where the body has it now (unless a
    // key rebuilt the scene meanwhile).
    const auto& objects = scene.run().objects();
    const dBodyID body =
        pressed_.objectIndex < static_cast<int>(objects.size()) ? objects[pressed_.objectIndex]->getBody() : nullptr;
    if (!body) {
      held_ = false;
      return;
    }
    dVector3 p;
    dBodyGetRelPointPos(body, grabLocal_[0], grabLocal_[1], grabLocal_[2], p);
    PickHit hit = pressed_;
    std::copy(p, p + 3, hit.point);
    scene.beginDrag(hit, hit.point);
    if (!scene.session().dragging()) {
      held_ = false;
      return;
    }
    pulling_ = true;
    grabbed_ = scene.draggedObject();
  }
  // Keep the grab distance along the new ray: the target follows the
  // cursor across the screen at the depth where the body was grabbed.
  glm::vec3 origin, direction;
  ray(scene, motion.x, motion.y, view, origin, direction);
  const glm::vec3 target = origin + direction * static_cast<float>(grabDistance_);
  const double t[3] = {target.x, target.y, target.z};
  scene.moveDrag(t);
}

WindowInput::WindowInput(const AbstractWindow& scene) : startTuning_(tuningOf(scene)) {}

void WindowInput::escape(AbstractWindow& scene) {
  if (scene.session().viewFlags().help) {
    scene.handleKey(SDLK_h, false);
    return;
  }
  if (tuningOf(scene) == startTuning_ || scene.session().notice() == QUIT_PROMPT) {
    scene.session().requestQuit();
    return;
  }
  scene.session().notify(QUIT_PROMPT);
}

bool WindowInput::handleEvent(const SDL_Event& event, AbstractWindow& scene, const ViewRect& view) {
  switch (event.type) {
    case SDL_QUIT:  // the window's close button: at once, as the window system expects
      scene.session().requestQuit();
      break;
    case SDL_KEYDOWN:
      // Auto-repeat would toggle switches and step settings at the repeat
      // rate (and a held Esc would answer its own prompt); one press is one action.
      if (event.key.keysym.sym == SDLK_ESCAPE) {
        // Esc first stops a rewind under way, where it is.
        if (scene.rewinding()) scene.cancelRewind();
        else if (!event.key.repeat) escape(scene);
        break;
      }
      if (camera_.handleKey(event.key, scene)) break;
      if (!event.key.repeat) scene.handleKey(event.key.keysym.sym, (event.key.keysym.mod & KMOD_SHIFT) != 0);
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
        if (pulling_) scene.endDrag();
        pulling_ = false;
      }
      camera_.releaseButton(event.button);
      break;
    case SDL_MOUSEMOTION:
      if (held_ && (event.motion.state & SDL_BUTTON_LMASK)) {
        moveLeft(event.motion, scene, view);
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
