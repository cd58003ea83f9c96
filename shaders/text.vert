// Text quads in DC-like pixel coordinates of the view (origin top-left, y down), taken to GL clip
// space by the pipeline's own matrices: glClipFromNpc · npcFromDc.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

layout(location = 0) in vec2 pixel;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 color;

uniform mat4 glClipFromDc;

out vec2 vUv;
out vec4 vColor;

void main() {
  vUv = uv;
  vColor = color;
  gl_Position = glClipFromDc * vec4(pixel, 0.0, 1.0);
}
