#pragma once

#include <GL/glew.h>

#include <string>

namespace odelab {

// One linked GLSL program built from a vertex and a fragment shader file.
// Construction throws ResourceError naming the file and quoting GL's log.
class ShaderProgram {
 public:
  ShaderProgram(const std::string& vertexPath, const std::string& fragmentPath);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const { glUseProgram(id_); }
  // Looks a uniform up by name; call once at setup and keep the location.
  // -1 (unused or absent) is harmless: glUniform* ignores it.
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace odelab
