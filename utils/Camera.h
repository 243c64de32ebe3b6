#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace odelab {

// The window's camera: an eye with yaw/pitch in degrees that orbits a target
// point in front of it (the pivot of mouse orbit and wheel zoom). It keeps
// the scene's start view ("home") so a user who flew away can come back.
// Pure math, no GL; the renderer asks it for the view matrix.
class Camera {
 public:
  // The scene's start view: recorded as home and taken now.
  void lookAt(const glm::vec3& eye, const glm::vec3& target);
  // Back to the start view, moved back along its line of sight as far as a
  // view narrower than REFERENCE_ASPECT needs to show as much across.
  void goHome();
  // The view's width over its height. While the camera is at home, a new
  // aspect refits the start view to it.
  void setAspect(float aspect);
  // Looks at a sphere (centre, radius) along the current direction, from
  // just far enough that all of it fits in the view.
  void frame(const glm::vec3& centre, float radius);

  // Moves eye and target along the view direction (forward) and its
  // horizontal right vector.
  void move(float forward, float right);
  // Mouse-look: positive yaw turns right, positive pitch looks up, about the
  // eye; pitch is kept short of straight up/down so the view never flips.
  void turn(float yawDegrees, float pitchDegrees);
  // Turns the eye about the target (same signs as turn(): positive pitch
  // lowers the eye, so that it looks up more).
  void orbit(float yawDegrees, float pitchDegrees);
  // Moves eye and target across the view: right and up, in metres.
  void pan(float right, float up);
  // Moves eye and target by `offset` (following a body).
  void shift(const glm::vec3& offset) {
    position_ += offset;
    atHome_ = false;
  }
  // Scales the eye's distance to the target (below 1: closer).
  void zoom(float factor);

  glm::vec3 position() const { return position_; }
  glm::vec3 target() const { return position_ + forward() * distance_; }
  float distance() const { return distance_; }
  glm::vec3 forward() const;
  glm::vec3 right() const;
  glm::vec3 up() const;
  glm::mat4 viewMatrix() const;
  // The ray from the eye through a window point given in normalised device
  // coordinates (x, y in [-1, 1], y up) for a window of the given aspect.
  void rayThrough(float ndcX, float ndcY, float aspect, glm::vec3& origin, glm::vec3& direction) const;
  float yawDegrees() const { return yaw_; }
  float pitchDegrees() const { return pitch_; }
  float fieldOfViewDegrees() const { return 60.0f; }
  bool atHome() const { return atHome_; }

  // The aspect the scenes' start views were chosen for (a 1280x720 window
  // with the panel open leaves about 4:3 to the scene).
  static constexpr float REFERENCE_ASPECT = 4.0f / 3.0f;

 private:
  void place(const glm::vec3& eye, const glm::vec3& target);

  glm::vec3 position_{0.0f, 5.0f, 15.0f};
  float yaw_ = -90.0f;   // looking along -z
  float pitch_ = -15.0f;
  float distance_ = 10.0f;
  glm::vec3 homeEye_{0.0f, 5.0f, 15.0f}, homeTarget_{0.0f, 0.0f, 0.0f};
  float aspect_ = REFERENCE_ASPECT;
  bool atHome_ = false;
};

// The help's lines for the mouse and the camera keys (the window's input
// handles them, not the key table).
std::vector<std::string> cameraHelpLines();

}  // namespace odelab
