#pragma once

#include <GL/glew.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "ShaderProgram.h"

namespace odelab {

// A vertex of unlit geometry: position and an 8-bit RGBA colour.
struct ColoredVertex {
  float position[3];
  std::uint8_t color[4];
};

struct Rgba {
  std::uint8_t r, g, b, a;
};

// Vertices gathered on the CPU for one draw, kept between frames: clear()
// keeps the capacity, so a steady frame allocates nothing.
class VertexList {
 public:
  void clear() { vertices_.clear(); }
  void point(const glm::vec3& p, Rgba c) { vertices_.push_back({{p.x, p.y, p.z}, {c.r, c.g, c.b, c.a}}); }
  void line(const glm::vec3& a, const glm::vec3& b, Rgba c) {
    point(a, c);
    point(b, c);
  }
  void append(const VertexList& other) {
    vertices_.insert(vertices_.end(), other.vertices_.begin(), other.vertices_.end());
  }
  std::size_t size() const { return vertices_.size(); }
  const std::vector<ColoredVertex>& vertices() const { return vertices_; }

 private:
  std::vector<ColoredVertex> vertices_;
};

// A vertex array and one dynamic vertex buffer of ColoredVertex. The buffer
// grows (doubling) to the largest upload seen and is then only overwritten.
class VertexStream {
 public:
  VertexStream();
  ~VertexStream();
  VertexStream(const VertexStream&) = delete;
  VertexStream& operator=(const VertexStream&) = delete;

  void upload(const VertexList& list);
  // Draws vertices [first, first + count) of the last upload.
  void draw(GLenum mode, std::size_t first, std::size_t count) const;

 private:
  GLuint vertexArray_ = 0;
  GLuint buffer_ = 0;
  std::size_t capacity_ = 0;  // in vertices
};

// The unlit shader (lines.vert / lines.frag).
class LineProgram {
 public:
  explicit LineProgram(const std::string& shaderDir);
  void use(const glm::mat4& matrix) const;

 private:
  ShaderProgram program_;
  GLint matrix_;
};

}  // namespace odelab
