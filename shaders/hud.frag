#version 330 core
// The HUD image already holds text over its translucent backing box.

in vec2 vTexCoord;

uniform sampler2D uText;

out vec4 fragColor;

void main() {
  fragColor = texture(uText, vTexCoord);
}
