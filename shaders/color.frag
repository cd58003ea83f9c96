#version 330 core
// Translucent overlay triangles (the view plane's window, user clip planes): the vertex colour.

in vec4 vColor;
uniform float alphaScale;  // < 1: the part of an overlay hidden behind objects (x-ray pass)

out vec4 fragColor;

void main() { fragColor = vec4(vColor.rgb, vColor.a * alphaScale); }
