#pragma once

#include <SDL2/SDL.h>

#include <glm/glm.hpp>

#include <vector>

#include "../AbstractWindow.h"
#include "CameraControl.h"

namespace odelab {

// Turns SDL input into scene actions: closing the window quits; Esc closes
// the help if it is open, else quits, asking once first (a notice) when the
// settings differ from the session's start (an Esc in a panel field never
// gets here: the field drops its text); the left button on a body drags it
// (a spring pulls the grabbed point toward the cursor, kept at its grab
// distance along the cursor's ray); the other buttons, the left one on empty
// space, the wheel, Home and W/S/A/D move the camera (CameraControl); every
// other key press goes to the scene's key table. Real and scripted (SDL_PushEvent) input take this path.
// Where the scene is drawn in the window, in SDL's window coordinates (those
// of mouse events): left, top, width, height.
struct ViewRect {
  int x, y, width, height;
};

class WindowInput {
 public:
  // Takes `scene`'s tuning as the session's start (see escape()).
  explicit WindowInput(const AbstractWindow& scene);

  // Returns true when the window's drawable size may have changed.
  bool handleEvent(const SDL_Event& event, AbstractWindow& scene, const ViewRect& view);

  // Once a frame after stepping: the camera follows the body double-clicked.
  void followBody(AbstractWindow& scene) { camera_.keepFollowing(scene); }

  // The drag to draw: the grabbed point on the body and the spring's
  // target. False when nothing is being dragged.
  bool dragLine(const AbstractWindow& scene, glm::vec3& grabbed, glm::vec3& target) const;

 private:
  // A press on a body holds it for a drag (true); false over empty space.
  bool pressLeft(const SDL_MouseButtonEvent& button, AbstractWindow& scene, const ViewRect& view);
  // The cursor moved with a body held: the drag begins, or its target moves.
  void moveLeft(const SDL_MouseMotionEvent& motion, AbstractWindow& scene, const ViewRect& view);
  void ray(const AbstractWindow& scene, int x, int y, const ViewRect& view, glm::vec3& origin,
           glm::vec3& direction) const;

  void escape(AbstractWindow& scene);

  CameraControl camera_;
  std::vector<double> startTuning_;  // tuningOf(scene) when the session began
  bool held_ = false;                 // the left button holds a body
  bool pulling_ = false;              // ... and has moved far enough to drag it
  PickHit pressed_;                   // where the press hit the body
  int pressX_ = 0, pressY_ = 0;       // where the press was, in window pixels
  double grabDistance_ = 0.0;         // along the ray, where the body was grabbed
  const AbstractObject* grabbed_ = nullptr;
  double grabLocal_[3] = {0, 0, 0};   // the grabbed point in the body's frame
};

// Flies the camera with W/S/A/D held, read from the keyboard state each
// frame so movement is smooth rather than paced by key repeat.
void moveCamera(AbstractWindow& scene, double frameSeconds);
// Whether a camera key (W/S/A/D) is held: the window must keep drawing.
bool cameraKeysHeld();

// Keeps SDL's relative mouse mode (hidden, captured cursor) in step with the
// scene's mouse-look flag, whoever changed it.
void syncMouseLook(const AbstractWindow& scene);

}  // namespace odelab
