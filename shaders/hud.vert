#version 330 core
// HUD text quad, generated from gl_VertexID (no vertex buffer): the four
// corners of uRect, given in pixels from the window's top-left corner.

uniform vec4 uRect;      // x, y, width, height in pixels
uniform vec2 uViewport;  // window size in pixels

out vec2 vTexCoord;

void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);  // (0,0) (1,0) (0,1) (1,1)
  vec2 pixel = uRect.xy + corner * uRect.zw;
  gl_Position = vec4(pixel.x / uViewport.x * 2.0 - 1.0, 1.0 - pixel.y / uViewport.y * 2.0, 0.0, 1.0);
  // The text image's first row is its top, as is the quad's first corner.
  vTexCoord = corner;
}
