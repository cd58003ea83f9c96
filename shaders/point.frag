// A disc with a dark rim and a one-pixel smooth edge.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

in vec4 gColor;
in vec2 gLocal;

uniform float sizePx;

uniform float alphaScale;  // < 1: the part of an overlay hidden behind objects (x-ray pass)

out vec4 fragColor;

void main() {
  float r = length(gLocal);
  float radius = 0.5 * sizePx;
  float coverage = clamp(radius + 0.5 - r, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  vec3 rgb = r > radius - 1.5 ? gColor.rgb * 0.35 : gColor.rgb;
  fragColor = vec4(rgb, gColor.a * coverage * alphaScale);
}
