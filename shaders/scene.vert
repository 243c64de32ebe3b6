#version 330 core
// Lit pass: world-space position and normal for per-pixel lighting, and the
// position as the light sees it, for the shadow-map lookup.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;   // inverse-transpose of uModel: boxes scale unevenly
uniform mat4 uViewProjection;
uniform mat4 uLightViewProjection;

out vec3 vWorldPosition;
out vec3 vNormal;
out vec4 vLightSpacePosition;

void main() {
  vec4 world = uModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
  vNormal = uNormalMatrix * aNormal;
  vLightSpacePosition = uLightViewProjection * world;
  gl_Position = uViewProjection * world;
}
