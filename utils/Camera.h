#pragma once

#include <glm/glm.hpp>

namespace odelab {

// A free-flying camera: position plus yaw/pitch in degrees. Pure math, no GL;
// the renderer asks it for the view matrix.
class Camera {
 public:
  void lookAt(const glm::vec3& eye, const glm::vec3& target);
  // Moves along the view direction (forward) and its horizontal right vector.
  void move(float forward, float right);
  // Mouse-look: positive yaw turns right, positive pitch looks up; pitch is
  // kept short of straight up/down so the view never flips.
  void turn(float yawDegrees, float pitchDegrees);

  glm::vec3 position() const { return position_; }
  glm::vec3 forward() const;
  glm::vec3 right() const;
  glm::mat4 viewMatrix() const;
  float yawDegrees() const { return yaw_; }
  float pitchDegrees() const { return pitch_; }
  float fieldOfViewDegrees() const { return 60.0f; }

 private:
  glm::vec3 position_{0.0f, 5.0f, 15.0f};
  float yaw_ = -90.0f;   // looking along -z
  float pitch_ = -15.0f;
};

}  // namespace odelab
