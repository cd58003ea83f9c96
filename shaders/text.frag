// Glyph coverage from the font atlas (ImGui's, single channel) times the text colour.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

in vec2 vUv;
in vec4 vColor;

uniform sampler2D atlas;

out vec4 fragColor;

void main() { fragColor = vec4(vColor.rgb, vColor.a * texture(atlas, vUv).r); }
