#version 330 core
// Light's depth pass: only the position as the light sees it matters.

layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uLightViewProjection;

void main() {
  gl_Position = uLightViewProjection * uModel * vec4(aPosition, 1.0);
}
