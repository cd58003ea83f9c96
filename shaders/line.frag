// Solid or dashed (dashPx > 0: dashPx on, dashPx off), with a one-pixel smooth edge.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

in vec4 gColor;
#ifndef GL_ES
noperspective
#endif
in vec3 gAlongAcrossW;  // see line.vert: divided by its z, linear in screen space
#if defined(USER_PLANES) && defined(GL_ES)
in float gClipDistance[6];
#endif

uniform float widthPx;
uniform float dashPx;

uniform float alphaScale;  // < 1: the part of an overlay hidden behind objects (x-ray pass)

out vec4 fragColor;

void main() {
#if defined(USER_PLANES) && defined(GL_ES)
  for (int k = 0; k < 6; ++k)
    if (gClipDistance[k] < 0.0) discard;
#endif
  float alongPx = gAlongAcrossW.x / gAlongAcrossW.z;
  float across = gAlongAcrossW.y / gAlongAcrossW.z;
  if (dashPx > 0.0 && mod(alongPx, 2.0 * dashPx) > dashPx) discard;
  float halfWidth = 0.5 * widthPx + 1.0;
  float edge = clamp(halfWidth * (1.0 - abs(across)), 0.0, 1.0);
  fragColor = vec4(gColor.rgb, gColor.a * edge * alphaScale);
}
