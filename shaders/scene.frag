#version 330 core
// Blinn-Phong from one directional light, shadowed through a depth map seen
// from that light (LearnOpenGL's shadow-mapping chapter). Ambient light is
// white so a shadow only darkens a surface and never changes its hue: the
// screenshot check relies on that to find lit and shadowed ground.

in vec3 vWorldPosition;
in vec3 vNormal;
in vec4 vLightSpacePosition;

uniform vec3 uColor;
uniform vec3 uToLight;          // unit vector from the surface towards the light
uniform vec3 uCameraPosition;
uniform sampler2D uShadowMap;
uniform float uBiasSlope;       // depth bias at grazing light, in depth-map units
uniform float uBiasMin;         // depth bias facing the light
uniform int uShadowRadius;      // shadow filter: (2r+1)^2 texels; 0 on a software renderer
uniform bool uChecker;          // 1 m checker on static geometry, for depth cues
uniform vec3 uFogColor;
uniform float uFogStart;
uniform float uFogEnd;

out vec4 fragColor;

// Ambient is stronger on upward faces (light from the sky) than downward
// ones, so faces turned from the sun still show their shape.
const float AMBIENT_DOWN = 0.24;
const float AMBIENT_UP = 0.36;
const float DIFFUSE = 0.72;
// A weak unshadowed light from the camera, so faces turned from the sun but
// towards the viewer keep their shape instead of going flat dark.
const float CAMERA_FILL = 0.18;
const float SPECULAR = 0.22;
const float SHININESS = 48.0;

// Fraction of light reaching the fragment (1 = fully lit), averaged over a
// 3x3 block of shadow-map texels so shadow edges are soft instead of jagged
// (one texel where the renderer runs on the CPU: a ninth of the lookups).
float lightVisibility(vec3 normal) {
  vec3 p = vLightSpacePosition.xyz / vLightSpacePosition.w * 0.5 + 0.5;
  // Outside the light's frustum nothing was rendered: treat as lit.
  if (p.z > 1.0 || any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
  // Slope-scaled bias: surfaces at a grazing angle to the light need more
  // offset to escape self-shadowing ("acne").
  float bias = max(uBiasSlope * (1.0 - dot(normal, uToLight)), uBiasMin);
  vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0));
  float lit = 0.0;
  for (int x = -uShadowRadius; x <= uShadowRadius; ++x) {
    for (int y = -uShadowRadius; y <= uShadowRadius; ++y) {
      float nearest = texture(uShadowMap, p.xy + vec2(x, y) * texel).r;
      lit += (p.z - bias > nearest) ? 0.0 : 1.0;
    }
  }
  float side = float(2 * uShadowRadius + 1);
  return lit / (side * side);
}

// Alternating 1 m cells, sampled a little inside the surface so that a face
// lying exactly on a cell boundary (the ground at y = 0) does not flicker.
// Where a cell shrinks towards a pixel the pattern fades out instead of
// breaking into moire.
float checker(vec3 normal) {
  vec3 p = vWorldPosition - normal * 0.01;
  vec3 cell = floor(p);
  float parity = mod(cell.x + cell.y + cell.z, 2.0);
  vec3 metresPerPixel = fwidth(p);
  float blur = max(max(metresPerPixel.x, metresPerPixel.y), metresPerPixel.z);
  float contrast = 0.1 * (1.0 - smoothstep(0.15, 0.5, blur));
  return 1.0 - contrast * parity - 0.5 * (0.1 - contrast);
}

void main() {
  vec3 normal = normalize(vNormal);
  vec3 toCamera = normalize(uCameraPosition - vWorldPosition);
  vec3 halfway = normalize(uToLight + toCamera);

  float diffuse = max(dot(normal, uToLight), 0.0);
  float specular = diffuse > 0.0 ? pow(max(dot(normal, halfway), 0.0), SHININESS) : 0.0;
  float visibility = diffuse > 0.0 ? lightVisibility(normal) : 0.0;

  vec3 albedo = uColor * (uChecker ? checker(normal) : 1.0);
  float ambient = mix(AMBIENT_DOWN, AMBIENT_UP, 0.5 + 0.5 * normal.y) + CAMERA_FILL * max(dot(normal, toCamera), 0.0);
  vec3 color = albedo * (ambient + DIFFUSE * diffuse * visibility) + vec3(SPECULAR * specular * visibility);

  // Fade the far ground into the sky so the infinite plane has a horizon.
  float distanceToCamera = length(uCameraPosition - vWorldPosition);
  float fog = clamp((distanceToCamera - uFogStart) / (uFogEnd - uFogStart), 0.0, 1.0);
  fragColor = vec4(mix(color, uFogColor, fog), 1.0);
}
