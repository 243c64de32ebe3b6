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
  // The ray from the eye through a window point given in normalised device
  // coordinates (x, y in [-1, 1], y up) for a window of the given aspect.
  void rayThrough(float ndcX, float ndcY, float aspect, glm::vec3& origin, glm::vec3& direction) const;
  float yawDegrees() const { return yaw_; }
  float pitchDegrees() const { return pitch_; }
  float fieldOfViewDegrees() const { return 60.0f; }

 private:
  glm::vec3 position_{0.0f, 5.0f, 15.0f};
  float yaw_ = -90.0f;   // looking along -z
  float pitch_ = -15.0f;
};

}  // namespace odelab
