// Flat: the object's colour, unlit. Shaded (SHADED defined): ambient, diffuse and specular
// (Blinn–Phong) from the scene's point lights, with the normal transformed by the inverse transpose
// (lecture notes 13.5); with FACE_NORMAL the normal of each fragment's plane (CPU polygons). The
// variants are separate programs: a software renderer runs every instruction of a shader, taken
// branches or not, so a flat program must not carry the lighting.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

in vec3 wcPosition;
in vec3 wcNormal;
in vec4 volumeNpcH;
#if defined(USER_PLANES) && defined(GL_ES)
in float gClipDistance[6];  // see scene.vert
#endif

// 0: no volume test; 1: keep what is inside the other camera's view volume; 2: keep what is outside.
// Blinn's boundary coordinates are linear in WC, and the interpolation of volumeNpcH is perspective-
// correct, so the test splits each polygon exactly where the CPU clipper cuts it (Hill 7.4).
uniform int volumeMode;
uniform vec3 color;
uniform float alpha;          // < 1: faded (outside the view volume)
uniform vec4 eyeWc;           // w = 1: the eye point; w = 0: the direction to the viewer (parallel)
// LIGHT_COUNT (1 … 4, with SHADED) is a constant, so the loop over the lights unrolls.
uniform vec3 lightPositions[4];
uniform vec3 lightColors[4];
uniform float ambient;

out vec4 fragColor;

void main() {
#if defined(USER_PLANES) && defined(GL_ES)
  for (int k = 0; k < 6; ++k)
    if (gClipDistance[k] < 0.0) discard;
#endif
#ifdef VOLUME_TEST
  // Only in the program that needs it: a shader that may discard loses the early depth test, which
  // on a software renderer means shading every hidden fragment too.
  if (volumeMode != 0) {
    vec4 v = volumeNpcH;
    bool inside = v.x >= 0.0 && v.w - v.x >= 0.0 && v.y >= 0.0 && v.w - v.y >= 0.0 && v.z >= 0.0 && v.w - v.z >= 0.0;
    if (inside != (volumeMode == 1)) discard;
  }
#endif
#ifndef SHADED
  fragColor = vec4(color, alpha);
#else
  vec3 toEye = normalize(eyeWc.w == 0.0 ? eyeWc.xyz : eyeWc.xyz - wcPosition);
#ifdef FACE_NORMAL
  // CPU polygons share their corners, which carry no normal: the plane's, from the change of the
  // position across the pixel (any two differences within a planar polygon span its plane), turned
  // to the side it is seen from, as Newell's normal flipped for a back face is.
  vec3 n = normalize(cross(dFdx(wcPosition), dFdy(wcPosition)));
  if (dot(n, toEye) < 0.0) n = -n;
#else
  vec3 n = normalize(wcNormal);
  if (!gl_FrontFacing) n = -n;  // polygons are lit from the side they are seen from
#endif
  vec3 c = ambient * color;
  for (int i = 0; i < LIGHT_COUNT; ++i) {
    vec3 l = normalize(lightPositions[i] - wcPosition);
    float diffuse = max(dot(n, l), 0.0);
    float h = max(dot(n, normalize(l + toEye)), 0.0);
    float h3 = h * h * h, h12 = (h3 * h3) * (h3 * h3);
    float specular = diffuse > 0.0 ? (h12 * h12) * (h12 * h12) : 0.0;  // h^48, by multiplications
    c += lightColors[i] * (diffuse * color + 0.3 * specular);
  }
  fragColor = vec4(min(c, vec3(1.0)), alpha);
#endif
}
