#include "Meshes.h"

#include <cmath>
#include <cstddef>

namespace odelab {

namespace {

struct Geometry {
  std::vector<MeshVertex> vertices;
  std::vector<GLuint> indices;
};

// Four vertices per face so each face has its own flat normal.
Geometry cubeGeometry() {
  // normal n and two axes u, v across the face with u x v = n, so the corners
  // below run counter-clockwise seen from outside.
  const float faces[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  Geometry g;
  for (const auto& face : faces) {
    const float* n = face[0];
    const float* u = face[1];
    const float* v = face[2];
    const GLuint base = static_cast<GLuint>(g.vertices.size());
    for (const auto& c : corners) {
      MeshVertex vertex{};
      for (int i = 0; i < 3; ++i) {
        vertex.position[i] = 0.5f * (n[i] + c[0] * u[i] + c[1] * v[i]);
        vertex.normal[i] = n[i];
      }
      g.vertices.push_back(vertex);
    }
    g.indices.insert(g.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return g;
}

// Latitude-longitude sphere; on a unit sphere the normal is the position.
Geometry sphereGeometry(int slices, int stacks) {
  Geometry g;
  const float pi = 3.14159265358979f;
  for (int stack = 0; stack <= stacks; ++stack) {
    const float polar = pi * static_cast<float>(stack) / static_cast<float>(stacks);
    for (int slice = 0; slice <= slices; ++slice) {
      const float azimuth = 2.0f * pi * static_cast<float>(slice) / static_cast<float>(slices);
      const float p[3] = {std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth)};
      g.vertices.push_back({{p[0], p[1], p[2]}, {p[0], p[1], p[2]}});
    }
  }
  const GLuint row = static_cast<GLuint>(slices + 1);
  for (GLuint stack = 0; stack < static_cast<GLuint>(stacks); ++stack) {
    for (GLuint slice = 0; slice < static_cast<GLuint>(slices); ++slice) {
      const GLuint a = stack * row + slice, b = a + row;
      // Counter-clockwise seen from outside (stack grows downwards, azimuth eastwards).
      g.indices.insert(g.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
  return g;
}

// Radius 1, length 1 along z, centred: a side with radial normals and two flat caps.
Geometry cylinderGeometry(int slices) {
  Geometry g;
  const float pi = 3.14159265358979f;
  auto around = [&](int slice, float& c, float& s) {
    const float azimuth = 2.0f * pi * static_cast<float>(slice) / static_cast<float>(slices);
    c = std::cos(azimuth);
    s = std::sin(azimuth);
  };
  for (int slice = 0; slice <= slices; ++slice) {
    float c, s;
    around(slice, c, s);
    g.vertices.push_back({{c, s, -0.5f}, {c, s, 0}});
    g.vertices.push_back({{c, s, 0.5f}, {c, s, 0}});
  }
  for (GLuint slice = 0; slice < static_cast<GLuint>(slices); ++slice) {
    const GLuint bottom = 2 * slice, top = bottom + 1, nextBottom = bottom + 2, nextTop = bottom + 3;
    g.indices.insert(g.indices.end(), {bottom, nextBottom, nextTop, bottom, nextTop, top});
  }
  for (const float z : {0.5f, -0.5f}) {
    const GLuint centre = static_cast<GLuint>(g.vertices.size());
    g.vertices.push_back({{0, 0, z}, {0, 0, z * 2}});
    for (int slice = 0; slice <= slices; ++slice) {
      float c, s;
      around(slice, c, s);
      g.vertices.push_back({{c, s, z}, {0, 0, z * 2}});
    }
    for (GLuint slice = 0; slice < static_cast<GLuint>(slices); ++slice) {
      const GLuint a = centre + 1 + slice, b = a + 1;
      // Counter-clockwise seen from outside: the top cap from +z, the bottom from -z.
      if (z > 0)
        g.indices.insert(g.indices.end(), {centre, a, b});
      else
        g.indices.insert(g.indices.end(), {centre, b, a});
    }
  }
  return g;
}

Geometry groundGeometry(float size) {
  const float h = 0.5f * size;
  Geometry g;
  g.vertices = {{{-h, 0, -h}, {0, 1, 0}}, {{-h, 0, h}, {0, 1, 0}}, {{h, 0, h}, {0, 1, 0}}, {{h, 0, -h}, {0, 1, 0}}};
  g.indices = {0, 1, 2, 0, 2, 3};
  return g;
}

Mesh makeMesh(const Geometry& g) { return Mesh(g.vertices, g.indices); }

}  // namespace

Mesh::Mesh(const std::vector<MeshVertex>& vertices, const std::vector<GLuint>& indices)
    : indexCount_(static_cast<GLsizei>(indices.size())) {
  glGenVertexArrays(1, &vertexArray_);
  glGenBuffers(1, &vertexBuffer_);
  glGenBuffers(1, &indexBuffer_);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(MeshVertex)), vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)), indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(offsetof(MeshVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                        reinterpret_cast<const void*>(offsetof(MeshVertex, normal)));
  glBindVertexArray(0);
}

Mesh::~Mesh() {
  glDeleteBuffers(1, &indexBuffer_);
  glDeleteBuffers(1, &vertexBuffer_);
  glDeleteVertexArrays(1, &vertexArray_);
}

void Mesh::draw() const {
  glBindVertexArray(vertexArray_);
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

Meshes::Meshes()
    : cube(makeMesh(cubeGeometry())),
      sphere(makeMesh(sphereGeometry(32, 16))),
      cylinder(makeMesh(cylinderGeometry(32))),
      ground(makeMesh(groundGeometry(GROUND_SIZE))) {}

}  // namespace odelab
