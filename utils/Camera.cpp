#include "Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace odelab {

namespace {
constexpr float PITCH_LIMIT = 89.0f;
}

void Camera::lookAt(const glm::vec3& eye, const glm::vec3& target) {
  position_ = eye;
  const glm::vec3 d = glm::normalize(target - eye);
  yaw_ = glm::degrees(std::atan2(d.z, d.x));
  pitch_ = std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -PITCH_LIMIT, PITCH_LIMIT);
}

glm::vec3 Camera::forward() const {
  const float yaw = glm::radians(yaw_), pitch = glm::radians(pitch_);
  return {std::cos(pitch) * std::cos(yaw), std::sin(pitch), std::cos(pitch) * std::sin(yaw)};
}

glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), glm::vec3(0, 1, 0))); }

void Camera::move(float forwardDistance, float rightDistance) {
  position_ += forward() * forwardDistance + right() * rightDistance;
}

void Camera::turn(float yawDegrees, float pitchDegrees) {
  yaw_ = std::fmod(yaw_ + yawDegrees, 360.0f);
  pitch_ = std::clamp(pitch_ + pitchDegrees, -PITCH_LIMIT, PITCH_LIMIT);
}

void Camera::rayThrough(float ndcX, float ndcY, float aspect, glm::vec3& origin, glm::vec3& direction) const {
  const float halfHeight = std::tan(glm::radians(fieldOfViewDegrees()) * 0.5f);
  const glm::vec3 f = forward(), r = right(), u = glm::cross(r, f);
  origin = position_;
  direction = glm::normalize(f + r * (ndcX * halfHeight * aspect) + u * (ndcY * halfHeight));
}

glm::mat4 Camera::viewMatrix() const { return glm::lookAt(position_, position_ + forward(), glm::vec3(0, 1, 0)); }

}  // namespace odelab
