#version 330 core
// Solid or dashed (dashPx > 0: dashPx on, dashPx off), with a one-pixel smooth edge.

in vec4 gColor;
noperspective in float gAlongPx;
noperspective in float gAcross;

uniform float widthPx;
uniform float dashPx;

uniform float alphaScale;  // < 1: the part of an overlay hidden behind objects (x-ray pass)

out vec4 fragColor;

void main() {
  if (dashPx > 0.0 && mod(gAlongPx, 2.0 * dashPx) > dashPx) discard;
  float halfWidth = 0.5 * widthPx + 1.0;
  float edge = clamp(halfWidth * (1.0 - abs(gAcross)), 0.0, 1.0);
  fragColor = vec4(gColor.rgb, gColor.a * edge * alphaScale);
}
