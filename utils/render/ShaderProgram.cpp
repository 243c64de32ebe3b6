#include "ShaderProgram.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "../ResourcePaths.h"
#include "../SafeFile.h"
#include "RenderError.h"

namespace odelab {

namespace {

std::string readFile(const std::string& path) {
  try {
    return readBoundedFile(path, MAX_SHADER_BYTES, "shader");
  } catch (const ReadRefused& error) {
    throw ResourceError(error.what());
  }
}

// The info log of a shader (glGetShaderiv, glGetShaderInfoLog) or a
// program (glGetProgramiv, glGetProgramInfoLog): only the getters differ.
std::string infoLog(GLuint object, PFNGLGETSHADERIVPROC getInteger, PFNGLGETSHADERINFOLOGPROC getLog) {
  GLint length = 0;
  getInteger(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  getLog(object, length, nullptr, log.data());
  return log.data();
}

std::string shaderLog(GLuint shader) { return infoLog(shader, glGetShaderiv, glGetShaderInfoLog); }
std::string programLog(GLuint program) { return infoLog(program, glGetProgramiv, glGetProgramInfoLog); }

#ifdef __EMSCRIPTEN__
// WebGL2 compiles GLSL ES 3.00: the desktop shaders' version line gives way
// to ES's, with the precisions ES wants declared.
std::string forWebGl(const std::string& source) {
  const std::string header = "#version 300 es\nprecision highp float;\nprecision highp sampler2D;\n";
  const std::size_t lineEnd = source.find('\n');
  if (source.rfind("#version", 0) != 0 || lineEnd == std::string::npos) return header + source;
  return header + source.substr(lineEnd + 1);
}
#else
const std::string& forWebGl(const std::string& source) { return source; }
#endif

GLuint compile(GLenum type, const std::string& path) {
  const std::string source = forWebGl(readFile(path));
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE) {
    const std::string log = shaderLog(shader);
    glDeleteShader(shader);
    throw ResourceError("cannot compile shader " + path + ":\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertexPath, const std::string& fragmentPath) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertexPath);
  GLuint fragment = 0;
  try {
    fragment = compile(GL_FRAGMENT_SHADER, fragmentPath);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  // The program keeps what it needs; the shader objects can go now.
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint linked = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    const std::string log = programLog(id_);
    glDeleteProgram(id_);
    throw ResourceError("cannot link shaders " + vertexPath + " + " + fragmentPath + ":\n" + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

}  // namespace odelab
