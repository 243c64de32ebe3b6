#version 330 core
// Unlit lines, points and flat triangles with a colour per vertex: the debug
// drawing in the world (uMatrix = view-projection) and the live plot on the
// screen (uMatrix maps window pixels to clip space).

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;

uniform mat4 uMatrix;

out vec4 vColor;

void main() {
  vColor = aColor;
  gl_Position = uMatrix * vec4(aPosition, 1.0);
#ifdef GL_ES
  // ES has no glPointSize: the debug drawing's points (POINT_PIXELS in
  // utils/render/DebugDraw.cpp) get their size here; lines ignore it.
  gl_PointSize = 6.0;
#endif
}
