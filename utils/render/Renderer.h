#pragma once

#include <GL/glew.h>

#include <glm/glm.hpp>
#include <string>

#include "../AbstractWindow.h"
#include "Meshes.h"
#include "ShaderProgram.h"
#include "ShadowMap.h"

namespace odelab {

// Draws the scene's objects with one directional light and its shadow: the
// same drawScene() runs twice, into the light's depth map and then lit into
// the window (LearnOpenGL's shadow-mapping layout).
class Renderer {
 public:
  // Loads scene.* and depth.* from shaderDir; throws RenderError.
  explicit Renderer(const std::string& shaderDir);

  // Renders into the default framebuffer, sized width x height pixels; in
  // wireframe (V) the bodies' triangles are drawn as lines, the ground filled.
  void render(const AbstractWindow& scene, int width, int height);
  // The camera's view-projection of the last render(), for the debug drawing.
  const glm::mat4& viewProjection() const { return viewProjection_; }

 private:
  // Uniform locations drawScene() sets per object, looked up once per program.
  struct ObjectUniforms {
    GLint model = -1;
    GLint normalMatrix = -1;
    GLint color = -1;
    GLint checker = -1;
  };
  static ObjectUniforms objectUniformsOf(const ShaderProgram& program);

  void drawScene(const AbstractWindow& scene, const ObjectUniforms& uniforms, bool wireframe = false) const;
  void setLitPassUniforms(const AbstractWindow& scene, int width, int height);

  ShaderProgram depthProgram_;
  ShaderProgram sceneProgram_;
  ObjectUniforms depthUniforms_;
  ObjectUniforms sceneUniforms_;
  GLint depthLightViewProjection_;
  struct {
    GLint viewProjection, lightViewProjection, toLight, cameraPosition, shadowMap;
    GLint biasSlope, biasMin, fogColor, fogStart, fogEnd;
  } lit_;
  Meshes meshes_;
  ShadowMap shadowMap_;
  glm::mat4 viewProjection_{1.0f};
};

}  // namespace odelab
