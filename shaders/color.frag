// Translucent overlay triangles (the view plane's window, user clip planes): the vertex colour.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

in vec4 vColor;
uniform float alphaScale;  // < 1: the part of an overlay hidden behind objects (x-ray pass)

out vec4 fragColor;

void main() { fragColor = vec4(vColor.rgb, vColor.a * alphaScale); }
