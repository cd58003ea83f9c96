// Translucent overlay triangles (the view plane's window, user clip planes) from the CPU pipeline,
// in any space S with a camera looking at it:
//   gl_Position = glClipFromNpc · npcFromVrc · vrcFromWc · wcFromMc · p,
// where "WC" is the space the observer stands in (WC for the world view, NPC for the NPC view).
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;

uniform mat4 wcFromMc;
uniform mat4 vrcFromWc;
uniform mat4 npcFromVrc;
uniform mat4 glClipFromNpc;

out vec4 vColor;

void main() {
  vColor = color;
  gl_Position = glClipFromNpc * npcFromVrc * vrcFromWc * (wcFromMc * vec4(position, 1.0));
}
