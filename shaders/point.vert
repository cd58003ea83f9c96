// Points as screen-aligned discs `sizePx` across (markers for VRP, PRP and probed vertices), without
// a geometry stage: one instance per point, a 4-vertex triangle strip, the corner from gl_VertexID.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;
precision highp int;

// Per instance (divisor 1): the point in the space of wcFromMc, and its colour.
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;

uniform mat4 wcFromMc;
uniform mat4 vrcFromWc;
uniform mat4 npcFromVrc;
uniform mat4 glClipFromNpc;
uniform vec2 viewportSize;
uniform float sizePx;

out vec4 gColor;
out vec2 gLocal;

void main() {
  vec4 p = glClipFromNpc * npcFromVrc * vrcFromWc * (wcFromMc * vec4(position, 1.0));
  gColor = color;
  if (p.w <= 0.0 || p.z < -p.w) {  // behind the observer or before its near plane: nothing drawn
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    gLocal = vec2(0.0);
    return;
  }
  // Corners in strip order: (−1, −1), (1, −1), (−1, 1), (1, 1).
  vec2 offset = vec2(gl_VertexID % 2 == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  vec2 r = vec2(sizePx * 0.5 + 1.0) / viewportSize * 2.0 * p.w;
  gl_Position = vec4(p.xy + offset * r, p.z, p.w);
  gLocal = offset * (sizePx * 0.5 + 1.0);
}
