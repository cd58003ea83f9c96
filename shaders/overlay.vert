#version 330 core
// Overlay geometry (lines, points, translucent quads) from the CPU pipeline, in any space S with a
// camera looking at it: gl_Position = glClipFromNpc · npcFromVrc · vrcFromWc · wcFromMc · p, where
// "WC" is the space the observer stands in (WC for the world view, NPC for the NPC view).

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;

uniform mat4 wcFromMc;
uniform mat4 vrcFromWc;
uniform mat4 npcFromVrc;
uniform mat4 glClipFromNpc;
// User clip planes in WC (DGL wiki), for the objects' edges in the wireframe styles.
uniform int userPlaneCount;
uniform vec4 userPlanesWc[6];

out vec4 vColor;
#ifdef USER_PLANES  // only in the edges' program for scenes with user planes: costly when written
out float gl_ClipDistance[6];
#endif

void main() {
  vColor = color;
  vec4 wc = wcFromMc * vec4(position, 1.0);
#ifdef USER_PLANES
  for (int i = 0; i < 6; ++i) gl_ClipDistance[i] = i < userPlaneCount ? dot(userPlanesWc[i], wc) : 1.0;
#endif
  gl_Position = glClipFromNpc * npcFromVrc * vrcFromWc * wc;
}
