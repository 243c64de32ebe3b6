#include "Camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace odelab {

namespace {
constexpr float PITCH_LIMIT = 89.0f;
// The orbit's pivot stays at least this far in front of the eye, and zoom
// goes no further out than the far reaches of any scene.
constexpr float MIN_DISTANCE = 0.2f, MAX_DISTANCE = 500.0f;
}  // namespace

void Camera::place(const glm::vec3& eye, const glm::vec3& target) {
  position_ = eye;
  const glm::vec3 offset = target - eye;
  distance_ = std::max(MIN_DISTANCE, glm::length(offset));
  const glm::vec3 d = glm::length(offset) > 0.0f ? offset / glm::length(offset) : glm::vec3(0, 0, -1);
  yaw_ = glm::degrees(std::atan2(d.z, d.x));
  pitch_ = std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -PITCH_LIMIT, PITCH_LIMIT);
  atHome_ = false;
}

void Camera::lookAt(const glm::vec3& eye, const glm::vec3& target) {
  homeEye_ = eye;
  homeTarget_ = target;
  goHome();
}

void Camera::goHome() {
  // A narrower view sees less across at the same distance: stepping back by
  // the ratio of the aspects shows the same width at the target's depth.
  const float back = std::max(1.0f, REFERENCE_ASPECT / std::max(aspect_, 0.05f));
  place(homeTarget_ + (homeEye_ - homeTarget_) * back, homeTarget_);
  atHome_ = true;
}

void Camera::setAspect(float aspect) {
  if (!(aspect > 0.0f) || aspect == aspect_) return;
  aspect_ = aspect;
  if (atHome_) goHome();
}

void Camera::frame(const glm::vec3& centre, float radius) {
  // The sphere fits when its radius subtends at most half the narrower of
  // the two fields of view.
  const float halfHeight = std::tan(glm::radians(fieldOfViewDegrees()) * 0.5f);
  const float halfNarrow = std::atan(halfHeight * std::min(1.0f, aspect_));
  const float distance = std::clamp(std::max(radius, 0.05f) / std::sin(halfNarrow), MIN_DISTANCE, MAX_DISTANCE);
  place(centre - forward() * distance, centre);
}

glm::vec3 Camera::forward() const {
  const float yaw = glm::radians(yaw_), pitch = glm::radians(pitch_);
  return {std::cos(pitch) * std::cos(yaw), std::sin(pitch), std::cos(pitch) * std::sin(yaw)};
}

glm::vec3 Camera::right() const { return glm::normalize(glm::cross(forward(), glm::vec3(0, 1, 0))); }

glm::vec3 Camera::up() const { return glm::cross(right(), forward()); }

void Camera::move(float forwardDistance, float rightDistance) {
  position_ += forward() * forwardDistance + right() * rightDistance;
  atHome_ = false;
}

void Camera::turn(float yawDegrees, float pitchDegrees) {
  yaw_ = std::fmod(yaw_ + yawDegrees, 360.0f);
  pitch_ = std::clamp(pitch_ + pitchDegrees, -PITCH_LIMIT, PITCH_LIMIT);
  atHome_ = false;
}

void Camera::orbit(float yawDegrees, float pitchDegrees) {
  const glm::vec3 pivot = target();
  turn(yawDegrees, pitchDegrees);
  position_ = pivot - forward() * distance_;
}

void Camera::pan(float rightDistance, float upDistance) {
  position_ += right() * rightDistance + up() * upDistance;
  atHome_ = false;
}

void Camera::zoom(float factor) {
  const glm::vec3 pivot = target();
  distance_ = std::clamp(distance_ * factor, MIN_DISTANCE, MAX_DISTANCE);
  position_ = pivot - forward() * distance_;
  atHome_ = false;
}

void Camera::rayThrough(float ndcX, float ndcY, float aspect, glm::vec3& origin, glm::vec3& direction) const {
  const float halfHeight = std::tan(glm::radians(fieldOfViewDegrees()) * 0.5f);
  const glm::vec3 f = forward(), r = right(), u = glm::cross(r, f);
  origin = position_;
  direction = glm::normalize(f + r * (ndcX * halfHeight * aspect) + u * (ndcY * halfHeight));
}

glm::mat4 Camera::viewMatrix() const { return glm::lookAt(position_, position_ + forward(), glm::vec3(0, 1, 0)); }

std::vector<std::string> cameraHelpLines() {
  return {
      "left mouse   drag a body with a spring; drag elsewhere to orbit the view;",
      "             double-click a body to follow it (elsewhere: stop)",
      "right mouse  drag to orbit the view about its target",
      "Shift+drag   pan the view (a middle-button drag too)",
      "mouse wheel  zoom toward the target",
      "W/S/A/D      fly the camera forward / back / left / right",
      "Home         back to the start view (Shift+Home: frame every body)",
  };
}

}  // namespace odelab
