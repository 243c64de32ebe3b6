#include "Renderer.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "../Box.h"
#include "../Plane.h"
#include "../Cylindrical.h"
#include "../Sphere.h"

namespace odelab {

namespace {

// High, over the default camera's right shoulder: the faces the camera sees
// are lit, and shadows fall away to the left, beside what casts them.
const glm::vec3 TO_LIGHT = glm::normalize(glm::vec3(0.3f, 1.0f, 0.25f));
const glm::vec3 SKY_COLOR(0.62f, 0.74f, 0.86f);
const glm::vec3 DISABLED_COLOR(0.5f, 0.5f, 0.5f);
// Biases in metres, turned into depth-map units with the map's depth range.
const float BIAS_SLOPE_METRES = 0.05f;
const float BIAS_MIN_METRES = 0.008f;
const float FOG_START = 80.0f, FOG_END = 400.0f;
const float NEAR_PLANE = 0.05f, FAR_PLANE = 1000.0f;

// A geom's world pose as a matrix. ODE's dMatrix3 is 3x4 row-major; glm is
// column-major, indexed [column][row]. dGeomGetPosition/Rotation already
// include any offset from the body, so geoms on composite bodies work too.
glm::mat4 poseOf(dGeomID geom) {
  const dReal* p = dGeomGetPosition(geom);
  const dReal* r = dGeomGetRotation(geom);
  glm::mat4 m(1.0f);
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) m[column][row] = static_cast<float>(r[row * 4 + column]);
    m[3][row] = static_cast<float>(p[row]);
  }
  return m;
}

// The infinite plane a*x + b*y + c*z = d as the ground quad: its y axis along
// the plane's normal, centred on the point of the plane nearest `focus`, so
// the quad's edge stays far from wherever the camera is.
glm::mat4 planePose(const Plane& plane, const glm::vec3& focus) {
  dVector4 params;
  plane.params(params);
  glm::vec3 normal(params[0], params[1], params[2]);
  const float length = glm::length(normal);
  if (length <= 0.0f) return glm::mat4(1.0f);
  normal /= length;
  const float offset = static_cast<float>(params[3]) / length;
  const glm::vec3 centre = focus - (glm::dot(normal, focus) - offset) * normal;
  const glm::vec3 helper = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  const glm::vec3 xAxis = glm::normalize(glm::cross(normal, helper));
  const glm::vec3 zAxis = glm::cross(xAxis, normal);
  return glm::mat4(glm::vec4(xAxis, 0), glm::vec4(normal, 0), glm::vec4(zAxis, 0), glm::vec4(centre, 1));
}

}  // namespace

Renderer::ObjectUniforms Renderer::objectUniformsOf(const ShaderProgram& program) {
  ObjectUniforms u;
  u.model = program.uniform("uModel");
  u.normalMatrix = program.uniform("uNormalMatrix");
  u.color = program.uniform("uColor");
  u.checker = program.uniform("uChecker");
  return u;
}

Renderer::Renderer(const std::string& shaderDir)
    : depthProgram_(shaderDir + "/depth.vert", shaderDir + "/depth.frag"),
      sceneProgram_(shaderDir + "/scene.vert", shaderDir + "/scene.frag"),
      depthUniforms_(objectUniformsOf(depthProgram_)),
      sceneUniforms_(objectUniformsOf(sceneProgram_)),
      depthLightViewProjection_(depthProgram_.uniform("uLightViewProjection")) {
  const ShaderProgram& p = sceneProgram_;
  lit_.viewProjection = p.uniform("uViewProjection");
  lit_.lightViewProjection = p.uniform("uLightViewProjection");
  lit_.toLight = p.uniform("uToLight");
  lit_.cameraPosition = p.uniform("uCameraPosition");
  lit_.shadowMap = p.uniform("uShadowMap");
  lit_.biasSlope = p.uniform("uBiasSlope");
  lit_.biasMin = p.uniform("uBiasMin");
  lit_.fogColor = p.uniform("uFogColor");
  lit_.fogStart = p.uniform("uFogStart");
  lit_.fogEnd = p.uniform("uFogEnd");
  lit_.shadowRadius = p.uniform("uShadowRadius");
}

void Renderer::render(const AbstractWindow& scene, int width, int height) {
  clearWindow();
  renderView(scene, scene.camera(), 0, 0, width, height);
}

void Renderer::clearWindow() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(SKY_COLOR.r, SKY_COLOR.g, SKY_COLOR.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void Renderer::renderView(const AbstractWindow& scene, const Camera& camera, int x, int y, int width, int height) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const glm::vec3 focus = camera.position();

  // Depth pass. Culling front faces stores each caster's far side, so lit
  // faces are compared against a depth well behind them: no shadow acne.
  // The ground quad faces the light and so drops out: it casts nothing.
  shadowMap_.fit(scene.bounds(), TO_LIGHT);
  shadowMap_.beginPass();
  glCullFace(GL_FRONT);
  depthProgram_.use();
  glUniformMatrix4fv(depthLightViewProjection_, 1, GL_FALSE, glm::value_ptr(shadowMap_.lightViewProjection()));
  drawScene(scene, focus, depthUniforms_);

  // Lit pass into the window (cleared by clearWindow), or into the scaled
  // target standing for this view, cleared here.
  target_.begin(x, y, width, height);
  if (target_.scale() < 1.0f) {
    glClearColor(SKY_COLOR.r, SKY_COLOR.g, SKY_COLOR.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  glCullFace(GL_BACK);
  sceneProgram_.use();
  setLitPassUniforms(camera, width, height);
  shadowMap_.bindTexture(GL_TEXTURE0);
  drawScene(scene, focus, sceneUniforms_, scene.session().viewFlags().wireframe);
  glBindVertexArray(0);
}

void Renderer::setLitPassUniforms(const Camera& camera, int width, int height) {
  const float aspect = height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
  const glm::mat4 projection =
      glm::perspective(glm::radians(camera.fieldOfViewDegrees()), aspect, NEAR_PLANE, FAR_PLANE);
  viewProjection_ = projection * camera.viewMatrix();
  const glm::vec3 eye = camera.position();
  glUniformMatrix4fv(lit_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection_));
  glUniformMatrix4fv(lit_.lightViewProjection, 1, GL_FALSE, glm::value_ptr(shadowMap_.lightViewProjection()));
  glUniform3fv(lit_.toLight, 1, glm::value_ptr(TO_LIGHT));
  glUniform3fv(lit_.cameraPosition, 1, glm::value_ptr(eye));
  glUniform1i(lit_.shadowMap, 0);
  glUniform1f(lit_.biasSlope, BIAS_SLOPE_METRES / shadowMap_.depthRange());
  glUniform1f(lit_.biasMin, BIAS_MIN_METRES / shadowMap_.depthRange());
  glUniform3fv(lit_.fogColor, 1, glm::value_ptr(SKY_COLOR));
  glUniform1f(lit_.fogStart, FOG_START);
  glUniform1f(lit_.fogEnd, FOG_END);
  glUniform1i(lit_.shadowRadius, shadowRadius_);
}

void Renderer::drawScene(const AbstractWindow& scene, const glm::vec3& focus, const ObjectUniforms& uniforms,
                         bool wireframe) const {
  for (const auto& object : scene.run().objects()) {
    if (!object->visible) continue;
    // One draw per part: a capsule is a cylinder and its two end spheres.
    struct Part {
      const Mesh* mesh;
      glm::mat4 model;
    };
    Part parts[3];
    int partCount = 0;
    switch (object->shape()) {
      case Shape::Box: {
        dVector3 sides;
        static_cast<const Box&>(*object).sides(sides);
        parts[partCount++] = {&meshes_.cube, glm::scale(poseOf(object->getGeom()), glm::vec3(sides[0], sides[1], sides[2]))};
        break;
      }
      case Shape::Sphere: {
        const float radius = static_cast<float>(static_cast<const Sphere&>(*object).radius());
        parts[partCount++] = {&meshes_.sphere, glm::scale(poseOf(object->getGeom()), glm::vec3(radius))};
        break;
      }
      case Shape::Capsule:
      case Shape::Cylinder: {
        double radius, length;
        static_cast<const Cylindrical&>(*object).dimensions(radius, length);
        const glm::mat4 pose = poseOf(object->getGeom());
        const float r = static_cast<float>(radius), half = static_cast<float>(length / 2);
        parts[partCount++] = {&meshes_.cylinder, glm::scale(pose, glm::vec3(r, r, static_cast<float>(length)))};
        if (object->shape() == Shape::Capsule)
          for (const float end : {-half, half})
            parts[partCount++] = {&meshes_.sphere, glm::scale(glm::translate(pose, glm::vec3(0, 0, end)), glm::vec3(r))};
        break;
      }
      case Shape::Plane:
        parts[partCount++] = {&meshes_.ground, planePose(static_cast<const Plane&>(*object), focus)};
        break;
    }
    const Color c = object->color;
    const glm::vec3 color = object->isEnabled() ? glm::vec3(c.r, c.g, c.b) : DISABLED_COLOR;
    glUniform3fv(uniforms.color, 1, glm::value_ptr(color));
    // Static geometry (ground, platforms) gets the checker for depth cues.
    glUniform1i(uniforms.checker, object->isFixed() ? 1 : 0);
    // Wireframe shows the bodies' triangles; the ground stays filled so the
    // scene keeps its floor (its two huge triangles would say nothing).
#ifdef __EMSCRIPTEN__
    // WebGL2 has no polygon mode: wireframe draws filled there.
    const bool lines = false;
    (void)wireframe;
#else
    const bool lines = wireframe && object->shape() != Shape::Plane;
#endif
    if (lines) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    for (int i = 0; i < partCount; ++i) {
      // Boxes and cylinders scale unevenly, so normals need the inverse-transpose.
      const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(parts[i].model));
      glUniformMatrix4fv(uniforms.model, 1, GL_FALSE, glm::value_ptr(parts[i].model));
      glUniformMatrix3fv(uniforms.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
      parts[i].mesh->draw();
    }
    if (lines) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
}

}  // namespace odelab
