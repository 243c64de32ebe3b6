#pragma once

#include <GL/glew.h>

#include <vector>

namespace odelab {

struct MeshVertex {
  float position[3];
  float normal[3];
};

// Indexed triangles in GPU buffers: attribute 0 = position, 1 = normal.
// Built once at start-up; drawing binds the vertex array and issues one call.
class Mesh {
 public:
  Mesh(const std::vector<MeshVertex>& vertices, const std::vector<GLuint>& indices);
  ~Mesh();
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;

  void draw() const;

 private:
  GLuint vertexArray_ = 0;
  GLuint vertexBuffer_ = 0;
  GLuint indexBuffer_ = 0;
  GLsizei indexCount_ = 0;
};

// The shapes every scene is drawn with; the model matrix scales them (a
// capsule is a cylinder and two spheres).
struct Meshes {
  Meshes();

  Mesh cube;    // side 1, centred on the origin
  Mesh sphere;  // radius 1, centred on the origin
  Mesh cylinder;  // radius 1, length 1 along z, centred on the origin
  Mesh ground;  // square of side GROUND_SIZE in the y = 0 plane, facing +y

  static constexpr float GROUND_SIZE = 1000.0f;
};

}  // namespace odelab
