#version 330 core
// Thick lines: each segment becomes a screen-aligned quad `widthPx` wide. The segment is first cut
// at GL's near plane (z ≥ −w) so the division below never sees w ≤ 0.

layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 viewportSize;
uniform float widthPx;

in vec4 vColor[];
#ifdef USER_PLANES
in gl_PerVertex {  // as overlay.vert writes it, with six clip distances
  vec4 gl_Position;
  float gl_PointSize;
  float gl_ClipDistance[6];
} gl_in[];
#endif
out vec4 gColor;
noperspective out float gAlongPx;   // distance from the segment's start, for dashes
noperspective out float gAcross;    // −1 … 1 across the line, for the antialiased edge
#ifdef USER_PLANES
out float gl_ClipDistance[6];       // the user clip planes, carried along the segment
#endif

void main() {
  vec4 p0 = gl_in[0].gl_Position;
  vec4 p1 = gl_in[1].gl_Position;
  float d0 = p0.z + p0.w, d1 = p1.z + p1.w;
  if (d0 < 0.0 && d1 < 0.0) return;
  float t0 = 0.0, t1 = 1.0;
  if (d0 < 0.0) t0 = d0 / (d0 - d1);
  if (d1 < 0.0) t1 = d0 / (d0 - d1);
  vec4 a = mix(p0, p1, t0), b = mix(p0, p1, t1);
  vec4 ca = mix(vColor[0], vColor[1], t0), cb = mix(vColor[0], vColor[1], t1);

  vec2 sa = (a.xy / a.w * 0.5 + 0.5) * viewportSize;
  vec2 sb = (b.xy / b.w * 0.5 + 0.5) * viewportSize;
  vec2 dir = sb - sa;
  float len = length(dir);
  dir = len > 1e-4 ? dir / len : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x) * (0.5 * widthPx + 1.0);  // 1 px margin for the smooth edge
  vec2 ext = dir * 0.5 * widthPx;                           // round-ish joints

  vec2 corners[4] = vec2[4](sa - ext + side, sa - ext - side, sb + ext + side, sb + ext - side);
  vec4 ends[4] = vec4[4](a, a, b, b);
  vec4 colors[4] = vec4[4](ca, ca, cb, cb);
  float along[4] = float[4](-0.5 * widthPx, -0.5 * widthPx, len + 0.5 * widthPx, len + 0.5 * widthPx);
  float ts[4] = float[4](t0, t0, t1, t1);
  for (int i = 0; i < 4; ++i) {
#ifdef USER_PLANES
    for (int k = 0; k < 6; ++k)
      gl_ClipDistance[k] = mix(gl_in[0].gl_ClipDistance[k], gl_in[1].gl_ClipDistance[k], ts[i]);
#endif
    vec2 ndc = corners[i] / viewportSize * 2.0 - 1.0;
    gl_Position = vec4(ndc * ends[i].w, ends[i].z, ends[i].w);
    gColor = colors[i];
    gAlongPx = along[i];
    gAcross = (i % 2 == 0) ? 1.0 : -1.0;
    EmitVertex();
  }
  EndPrimitive();
}
