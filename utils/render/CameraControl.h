#pragma once

#include <SDL2/SDL.h>

#include "../AbstractWindow.h"

namespace odelab {

// The camera as the mouse and the keyboard move it, apart from body drags:
// a left drag on empty space (or a right drag) orbits the target, a middle
// drag (or Shift with a left or right drag) pans, the wheel zooms toward
// the target, Home returns to the scene's start view, Shift+Home frames
// every body, a W/S/A/D press nudges the camera one step (held keys fly
// it, moveCamera()), and a double click on a body follows it.
class CameraControl {
 public:
  // A key for the camera: true when it took it (the scene must not see it).
  bool handleKey(const SDL_KeyboardEvent& key, AbstractWindow& scene);
  // A button press on empty space starts an orbit or a pan; true when taken.
  bool pressButton(const SDL_MouseButtonEvent& button);
  // Ends the orbit or pan the button started; true when one was under way.
  bool releaseButton(const SDL_MouseButtonEvent& button);
  // Motion during an orbit or a pan; viewHeight in window coordinates
  // (a pan moves the target with the cursor). True when taken.
  bool moveMouse(const SDL_MouseMotionEvent& motion, Camera& camera, int viewHeight);
  void wheel(const SDL_MouseWheelEvent& wheel, Camera& camera);
  bool active() const { return mode_ != Mode::None; }
  // Follows object `index` of the scene: the camera moves as the body does
  // (-1: stop). Home and Shift+Home stop it too.
  void follow(int index, const AbstractWindow& scene);
  // Once a frame, after stepping: carries the camera along with the body.
  void keepFollowing(AbstractWindow& scene);

 private:
  enum class Mode { None, Orbit, Pan };
  Mode mode_ = Mode::None;
  Uint8 button_ = 0;
  int followed_ = -1;                   // index into scene.objects()
  const AbstractObject* followedObject_ = nullptr;  // to notice a rebuilt scene
  glm::vec3 followedAt_{0.0f};          // where it was last frame
};

// Looks at every body of the scene (not the ground) from the current direction.
void frameScene(AbstractWindow& scene);

}  // namespace odelab
