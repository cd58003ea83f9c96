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

out vec4 vColor;

void main() {
  vColor = color;
  gl_Position = glClipFromNpc * npcFromVrc * vrcFromWc * wcFromMc * vec4(position, 1.0);
}
