#include "ShadowMap.h"

#include <cmath>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

#include "RenderError.h"

namespace odelab {

ShadowMap::ShadowMap() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, SIZE, SIZE, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  // Nearest: the shader does its own 3x3 filtering of the depth comparisons.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
#ifdef __EMSCRIPTEN__
  // WebGL2 has no border colour: the edge texels repeat, and the shader's
  // bounds test treats what lies outside the map as unshadowed.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
#else
  // Beyond the map's edge the depth reads as farthest, i.e. unshadowed.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float farthest[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, farthest);
#endif

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
  // Depth only: no colour buffer to draw into or read from.
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);  // glDrawBuffer(GL_NONE), which ES lacks
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
    throw RenderError("shadow-map framebuffer incomplete (status " + std::to_string(status) + ")");
  }
}

ShadowMap::~ShadowMap() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
}

void ShadowMap::fit(const SceneBounds& bounds, const glm::vec3& toLight) {
  const glm::vec3 centre(bounds.centre[0], bounds.centre[1], bounds.centre[2]);
  const float radius = static_cast<float>(bounds.radius > 0 ? bounds.radius : 1.0);
  // The light stands two radii out; the box spans the sphere plus a radius of
  // margin on the light's side, so casters just outside it still cast.
  const glm::vec3 eye = centre + toLight * (2.0f * radius);
  const glm::vec3 up = std::fabs(toLight.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::mat4 view = glm::lookAt(eye, centre, up);
  const float nearPlane = 0.0f, farPlane = 3.0f * radius;
  const glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, nearPlane, farPlane);
  lightViewProjection_ = projection * view;
  depthRange_ = farPlane - nearPlane;
}

void ShadowMap::beginPass() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, SIZE, SIZE);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::bindTexture(GLenum unit) const {
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, texture_);
}

}  // namespace odelab
