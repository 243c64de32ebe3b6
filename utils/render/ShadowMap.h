#pragma once

#include <GL/glew.h>

#include <glm/glm.hpp>

#include "../AbstractWindow.h"

namespace odelab {

// The depth texture rendered from the directional light, and the light's
// orthographic view-projection fitted around the scene's bounding sphere so
// its 2048^2 texels cover what the scene shows and no more.
class ShadowMap {
 public:
  static constexpr int SIZE = 2048;

  ShadowMap();
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  // toLight: unit vector from the scene towards the light.
  void fit(const SceneBounds& bounds, const glm::vec3& toLight);
  const glm::mat4& lightViewProjection() const { return lightViewProjection_; }
  // World distance spanned by depth values 0..1, to express biases in metres.
  float depthRange() const { return depthRange_; }

  // Binds the depth framebuffer, sets the viewport to it and clears it.
  void beginPass() const;
  void bindTexture(GLenum unit) const;

 private:
  GLuint framebuffer_ = 0;
  GLuint texture_ = 0;
  glm::mat4 lightViewProjection_{1.0f};
  float depthRange_ = 1.0f;
};

}  // namespace odelab
