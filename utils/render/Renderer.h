#pragma once

#include <GL/glew.h>

#include <glm/glm.hpp>
#include <string>

#include "../AbstractWindow.h"
#include "Meshes.h"
#include "ShaderProgram.h"
#include "ScaledTarget.h"
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
  // The compare window's pieces: the whole window cleared to the sky, then
  // each scene drawn by `camera` into its own x, y, width, height (pixels
  // from the bottom left), each followed by what is drawn over it and present().
  void clearWindow();
  void renderView(const AbstractWindow& scene, const Camera& camera, int x, int y, int width, int height);
  // A software renderer's cheaper look: shadows filtered over one texel
  // rather than 3x3 (harder shadow edges, a ninth of the lookups), and the
  // scene drawn at SOFTWARE_SCALE of the view's size in each direction.
  void setSoftware(bool software) {
    shadowRadius_ = software ? 0 : 1;
    target_.setScale(software ? SOFTWARE_SCALE : 1.0f);
  }
  static constexpr float SOFTWARE_SCALE = 0.7f;
  // After render() and anything else drawn into the scene (the debug
  // drawing): the scene onto the window, where it was drawn scaled.
  void present() { target_.present(); }
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

  void drawScene(const AbstractWindow& scene, const glm::vec3& focus, const ObjectUniforms& uniforms,
                 bool wireframe = false) const;
  void setLitPassUniforms(const Camera& camera, int width, int height);

  ShaderProgram depthProgram_;
  ShaderProgram sceneProgram_;
  ObjectUniforms depthUniforms_;
  ObjectUniforms sceneUniforms_;
  GLint depthLightViewProjection_;
  struct {
    GLint viewProjection, lightViewProjection, toLight, cameraPosition, shadowMap;
    GLint biasSlope, biasMin, fogColor, fogStart, fogEnd, shadowRadius;
  } lit_;
  Meshes meshes_;
  ShadowMap shadowMap_;
  glm::mat4 viewProjection_{1.0f};
  int shadowRadius_ = 1;
  ScaledTarget target_;
};

}  // namespace odelab
