#pragma once
// The renderer's GL header in the browser build (this folder comes first on
// the web build's include path). Emscripten maps the desktop-named GL calls
// onto WebGL2, so no loader is needed: GLEW's entry points become no-ops,
// and the few desktop switches WebGL2 lacks are dropped here rather than at
// every call.

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#define GLEW_OK 0
#define GLEW_ERROR_NO_GLX_DISPLAY 4
static GLboolean glewExperimental;
inline GLenum glewInit() { return GLEW_OK; }
inline const GLubyte* glewGetErrorString(GLenum) { return reinterpret_cast<const GLubyte*>("no error"); }

// WebGL2 fixes multisampling when the context is made (the canvas's
// antialias flag); GL_MULTISAMPLE is not a capability it can switch.
inline void odelabWebEnable(GLenum cap) {
  if (cap != GL_MULTISAMPLE) glEnable(cap);
}
inline void odelabWebDisable(GLenum cap) {
  if (cap != GL_MULTISAMPLE) glDisable(cap);
}
#define glEnable odelabWebEnable
#define glDisable odelabWebDisable
// Points take their size from gl_PointSize in the vertex shader
// (shaders/lines.vert under GL_ES).
#define glPointSize(size) ((void)(size))
