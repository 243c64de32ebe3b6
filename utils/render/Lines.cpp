#include "Lines.h"

#include <cstddef>
#include <glm/gtc/type_ptr.hpp>

namespace odelab {

VertexStream::VertexStream() {
  glGenVertexArrays(1, &vertexArray_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ColoredVertex),
                        reinterpret_cast<const void*>(offsetof(ColoredVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ColoredVertex),
                        reinterpret_cast<const void*>(offsetof(ColoredVertex, color)));
  glBindVertexArray(0);
}

VertexStream::~VertexStream() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vertexArray_);
}

void VertexStream::upload(const VertexList& list) {
  const std::size_t count = list.size();
  if (count == 0) return;
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  if (count > capacity_) {
    std::size_t grown = capacity_ > 0 ? capacity_ : 1024;
    while (grown < count) grown *= 2;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(grown * sizeof(ColoredVertex)), nullptr, GL_DYNAMIC_DRAW);
    capacity_ = grown;
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(ColoredVertex)),
                  list.vertices().data());
}

void VertexStream::draw(GLenum mode, std::size_t first, std::size_t count) const {
  if (count == 0) return;
  glBindVertexArray(vertexArray_);
  glDrawArrays(mode, static_cast<GLint>(first), static_cast<GLsizei>(count));
  glBindVertexArray(0);
}

LineProgram::LineProgram(const std::string& shaderDir)
    : program_(shaderDir + "/lines.vert", shaderDir + "/lines.frag"), matrix_(program_.uniform("uMatrix")) {}

void LineProgram::use(const glm::mat4& matrix) const {
  program_.use();
  glUniformMatrix4fv(matrix_, 1, GL_FALSE, glm::value_ptr(matrix));
}

}  // namespace odelab
