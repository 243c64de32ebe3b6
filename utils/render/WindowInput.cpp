#include "WindowInput.h"

namespace odelab {

namespace {

const float DEGREES_PER_PIXEL = 0.15f;
const float METRES_PER_SECOND = 8.0f;

// Keys the front end keeps for itself: they never reach the key table.
bool isFrontEndKey(SDL_Keycode key) {
  return key == SDLK_ESCAPE || key == SDLK_w || key == SDLK_a || key == SDLK_s || key == SDLK_d;
}

}  // namespace

bool handleEvent(const SDL_Event& event, AbstractWindow& scene) {
  switch (event.type) {
    case SDL_QUIT:
      scene.requestQuit();
      break;
    case SDL_KEYDOWN:
      if (event.key.keysym.sym == SDLK_ESCAPE) scene.requestQuit();
      // Auto-repeat would toggle switches and step settings at the repeat
      // rate; one press is one action.
      if (!isFrontEndKey(event.key.keysym.sym) && !event.key.repeat)
        scene.handleKey(event.key.keysym.sym, (event.key.keysym.mod & KMOD_SHIFT) != 0);
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.button == SDL_BUTTON_LEFT) scene.toggleMouseLook();
      break;
    case SDL_MOUSEMOTION:
      // Screen y grows downwards: moving the mouse up looks up.
      if (scene.mouseLook())
        scene.camera().turn(static_cast<float>(event.motion.xrel) * DEGREES_PER_PIXEL,
                            -static_cast<float>(event.motion.yrel) * DEGREES_PER_PIXEL);
      break;
    case SDL_WINDOWEVENT:
      return event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED;
    default:
      break;
  }
  return false;
}

void moveCamera(AbstractWindow& scene, double frameSeconds) {
  const Uint8* keys = SDL_GetKeyboardState(nullptr);
  const float forward = static_cast<float>(keys[SDL_SCANCODE_W] - keys[SDL_SCANCODE_S]);
  const float right = static_cast<float>(keys[SDL_SCANCODE_D] - keys[SDL_SCANCODE_A]);
  if (forward == 0.0f && right == 0.0f) return;
  const float step = METRES_PER_SECOND * static_cast<float>(frameSeconds);
  scene.camera().move(forward * step, right * step);
}

void syncMouseLook(const AbstractWindow& scene) {
  const SDL_bool wanted = scene.mouseLook() ? SDL_TRUE : SDL_FALSE;
  // May fail where relative mode is unsupported; the camera still turns by motion.
  if (SDL_GetRelativeMouseMode() != wanted) SDL_SetRelativeMouseMode(wanted);
}

}  // namespace odelab
