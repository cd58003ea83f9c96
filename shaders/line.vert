// Thick lines without a geometry stage (GLSL ES 3.00 and WebGL2 have none): one instance per
// segment, drawn as a 4-vertex triangle strip whose corner comes from gl_VertexID. Each segment is
// first cut at GL's near plane (z ≥ −w) so the division below never sees w ≤ 0, then becomes a
// screen-aligned quad `widthPx` wide plus a 1 px margin on each side for the smooth edge, extended
// by widthPx / 2 past both ends (round-ish joints).
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;
precision highp int;

// Per instance (divisor 1): the segment's end points in the space of wcFromMc, and their colours.
layout(location = 0) in vec3 position0;
layout(location = 1) in vec4 color0;
layout(location = 2) in vec3 position1;
layout(location = 3) in vec4 color1;

uniform mat4 wcFromMc;
uniform mat4 vrcFromWc;
uniform mat4 npcFromVrc;
uniform mat4 glClipFromNpc;
uniform vec2 viewportSize;
uniform float widthPx;
// User clip planes in WC (DGL wiki, glClipPlane), for the objects' edges in the wireframe styles.
uniform int userPlaneCount;
uniform vec4 userPlanesWc[6];

out vec4 gColor;
// (distance from the segment's start in px, −1 … 1 across the line, 1), linear in screen space for
// the dashes and the smooth edge. GLSL ES 3.00 has no `noperspective`: there the three are sent
// times w, interpolated with perspective, and line.frag divides by the third (which is then the
// interpolated w), which gives the same screen-linear values; on desktop GL the third stays 1.
#ifdef GL_ES
out vec3 gAlongAcrossW;
#define SCREEN_LINEAR_SCALE(w) (w)
#else
noperspective out vec3 gAlongAcrossW;
#define SCREEN_LINEAR_SCALE(w) 1.0
#endif
#ifdef USER_PLANES
#ifdef GL_ES  // no gl_ClipDistance: line.frag discards where a distance is negative
out float gClipDistance[6];
#else
out float gl_ClipDistance[6];
#endif
#endif

float clipDistance(int k, vec4 wc) { return k < userPlaneCount ? dot(userPlanesWc[k], wc) : 1.0; }

void main() {
  int corner = gl_VertexID;  // 0, 1 at the start, 2, 3 at the end; even: on the left of the segment
  bool atEnd = corner >= 2;
  vec4 wc0 = wcFromMc * vec4(position0, 1.0);
  vec4 wc1 = wcFromMc * vec4(position1, 1.0);
  vec4 p0 = glClipFromNpc * npcFromVrc * vrcFromWc * wc0;
  vec4 p1 = glClipFromNpc * npcFromVrc * vrcFromWc * wc1;
  float d0 = p0.z + p0.w, d1 = p1.z + p1.w;
  if (d0 < 0.0 && d1 < 0.0) {  // wholly before the near plane: a degenerate strip outside the volume
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    gColor = vec4(0.0);
    gAlongAcrossW = vec3(0.0, 0.0, 1.0);
#ifdef USER_PLANES
    for (int k = 0; k < 6; ++k) {
#ifdef GL_ES
      gClipDistance[k] = -1.0;
#else
      gl_ClipDistance[k] = -1.0;
#endif
    }
#endif
    return;
  }
  float t0 = 0.0, t1 = 1.0;
  if (d0 < 0.0) t0 = d0 / (d0 - d1);
  if (d1 < 0.0) t1 = d0 / (d0 - d1);
  vec4 a = mix(p0, p1, t0), b = mix(p0, p1, t1);

  vec2 sa = (a.xy / a.w * 0.5 + 0.5) * viewportSize;
  vec2 sb = (b.xy / b.w * 0.5 + 0.5) * viewportSize;
  vec2 dir = sb - sa;
  float len = length(dir);
  dir = len > 1e-4 ? dir / len : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x) * (0.5 * widthPx + 1.0);  // 1 px margin for the smooth edge
  vec2 ext = dir * 0.5 * widthPx;                           // round-ish joints

  vec2 base = atEnd ? sb + ext : sa - ext;
  vec2 pixel = corner % 2 == 0 ? base + side : base - side;
  vec4 end = atEnd ? b : a;
  float t = atEnd ? t1 : t0;
#ifdef USER_PLANES
  for (int k = 0; k < 6; ++k) {  // carried along the cut segment
    float dk = mix(clipDistance(k, wc0), clipDistance(k, wc1), t);
#ifdef GL_ES
    gClipDistance[k] = dk;
#else
    gl_ClipDistance[k] = dk;
#endif
  }
#endif
  vec2 ndc = pixel / viewportSize * 2.0 - 1.0;
  gl_Position = vec4(ndc * end.w, end.z, end.w);
  gColor = atEnd ? mix(color0, color1, t1) : mix(color0, color1, t0);
  float along = atEnd ? len + 0.5 * widthPx : -0.5 * widthPx;
  float across = corner % 2 == 0 ? 1.0 : -1.0;
  gAlongAcrossW = vec3(along, across, 1.0) * SCREEN_LINEAR_SCALE(end.w);
}
