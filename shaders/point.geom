#version 330 core
// Points as screen-aligned discs `sizePx` across (markers for VRP, PRP and probed vertices).

layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 viewportSize;
uniform float sizePx;

in vec4 vColor[];
out vec4 gColor;
out vec2 gLocal;

void main() {
  vec4 p = gl_in[0].gl_Position;
  if (p.w <= 0.0 || p.z < -p.w) return;  // behind the observer or before its near plane
  vec2 r = vec2(sizePx * 0.5 + 1.0) / viewportSize * 2.0 * p.w;
  vec2 offsets[4] = vec2[4](vec2(-1, -1), vec2(1, -1), vec2(-1, 1), vec2(1, 1));
  for (int i = 0; i < 4; ++i) {
    gl_Position = vec4(p.xy + offsets[i] * r, p.z, p.w);
    gColor = vColor[0];
    gLocal = offsets[i] * (sizePx * 0.5 + 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
