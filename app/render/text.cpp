#include "app/render/text.h"

#include "app/views/view_camera.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

namespace vplab {

TextRenderer::TextRenderer(const GladGLContext& gl, float scale)
    : gl_(&gl),
      atlas_(std::make_unique<FontAtlas>(scale)),
      program_(gl::Program::fromFiles(gl, {"text.vert", "text.frag"})),
      texture_(gl::makeTexture(gl)),
      vao_(gl::makeVertexArray(gl)),
      vbo_(gl::makeBuffer(gl)) {
  const FontAtlas::Alpha8 a = atlas_->alpha8();
  gl.BindTexture(GL_TEXTURE_2D, texture_.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, a.width, a.height, 0, GL_RED, GL_UNSIGNED_BYTE, a.pixels);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  const GLsizei stride = 8 * sizeof(float);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, nullptr);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(2 * sizeof(float)));
  gl.EnableVertexAttribArray(2);
  gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(4 * sizeof(float)));
  gl.BindVertexArray(0);
}

TextRenderer::~TextRenderer() = default;

void TextRenderer::appendText(const PlacedLabel& label, const glm::vec2& origin, const glm::vec4& color,
                              std::vector<float>& out) const {
  const ImFont* f = atlas_->font(label.size);
  float x = origin.x;
  const char* s = label.text.c_str();
  const char* end = s + label.text.size();
  while (s < end) {
    unsigned int c = 0;
    s += ImTextCharFromUtf8(&c, s, end);
    if (c == 0) break;
    const ImFontGlyph* g = f->FindGlyph(ImWchar(c));
    if (!g) continue;
    const float x0 = x + g->X0, y0 = origin.y + g->Y0, x1 = x + g->X1, y1 = origin.y + g->Y1;
    const float quad[6][4] = {{x0, y0, g->U0, g->V0}, {x1, y0, g->U1, g->V0}, {x1, y1, g->U1, g->V1},
                              {x0, y0, g->U0, g->V0}, {x1, y1, g->U1, g->V1}, {x0, y1, g->U0, g->V1}};
    for (const auto& v : quad) out.insert(out.end(), {v[0], v[1], v[2], v[3], color.r, color.g, color.b, color.a});
    x += g->AdvanceX;
  }
}

void TextRenderer::draw(const std::vector<PlacedLabel>& labels, const glm::vec3& outline, int width, int height) {
  placed_.clear();
  if (labels.empty()) return;
  std::vector<float> vertices;
  for (const PlacedLabel& l : labels) {
    placed_.emplace_back(l.topLeft.x, l.topLeft.y, l.topLeft.x + l.extent.x, l.topLeft.y + l.extent.y);
    if (l.shadow) {
      const glm::vec4 dark(outline, 0.75f * l.color.a);
      for (const glm::vec2 o : {glm::vec2(-1, 0), glm::vec2(1, 0), glm::vec2(0, -1), glm::vec2(0, 1)})
        appendText(l, l.topLeft + o, dark, vertices);
    }
    appendText(l, l.topLeft, l.color, vertices);
  }
  const GladGLContext& gl = *gl_;
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  program_.use();
  program_.set("glClipFromDc", glClipFromPixels(width, height));
  program_.set("atlas", 0);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, texture_.id());
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_.id());
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STREAM_DRAW);
  gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size() / 8));
  gl.BindVertexArray(0);
  gl.Enable(GL_DEPTH_TEST);
}

}  // namespace vplab
