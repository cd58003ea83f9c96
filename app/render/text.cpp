#include "app/render/text.h"

#include "app/render/view_camera.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

#include <filesystem>

namespace vplab {

namespace {

constexpr const char* kFontFiles[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"};
// Latin, Greek (φ, α), punctuation, super- and subscripts, arrows (→) and mathematical operators (≤, ÷ is Latin-1).
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070, 0x209F,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0};

}  // namespace

TextRenderer::TextRenderer(const GladGLContext& gl, float scale)
    : gl_(&gl),
      atlas_(std::make_unique<ImFontAtlas>()),
      program_(gl::Program::fromFiles(gl, {"text.vert", "text.frag"})),
      texture_(gl::makeTexture(gl)),
      vao_(gl::makeVertexArray(gl)),
      vbo_(gl::makeBuffer(gl)) {
  scale_ = scale;
  for (const char* file : kFontFiles) {
    if (!std::filesystem::exists(file)) continue;
    label_ = atlas_->AddFontFromFileTTF(file, 15.f * scale, nullptr, kGlyphRanges);
    title_ = atlas_->AddFontFromFileTTF(file, 20.f * scale, nullptr, kGlyphRanges);
    break;
  }
  if (!label_ || !title_) {
    ImFontConfig config;
    config.SizePixels = 13.f * std::max(1.f, std::round(scale));
    label_ = title_ = atlas_->AddFontDefault(&config);
  }
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  atlas_->GetTexDataAsAlpha8(&pixels, &w, &h);
  gl.BindTexture(GL_TEXTURE_2D, texture_.id());
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, w, h, 0, GL_RED, GL_UNSIGNED_BYTE, pixels);
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

std::vector<glm::vec2> placeLabels(const std::vector<TextLabel>& labels,
                                   const std::function<Vec2(const TextLabel&)>& measure, int width, int height,
                                   float markerClearPx) {
  std::vector<glm::vec2> out;
  std::vector<glm::vec4> placed;  // x0, y0, x1, y1 of the labels so far
  std::vector<glm::vec2> markers;
  for (const TextLabel& l : labels)
    if (l.marker) markers.emplace_back(*l.marker);
  for (const TextLabel& l : labels) {
    const glm::vec2 size(measure(l));
    glm::vec2 anchored(l.pixel);
    switch (l.anchor) {
      case Anchor::topLeft: break;
      case Anchor::center: anchored -= size * 0.5f; break;
      case Anchor::left: anchored.y -= size.y * 0.5f; break;
      case Anchor::bottomLeft: anchored.y -= size.y; break;
      case Anchor::topCenter: anchored.x -= size.x * 0.5f; break;
    }
    const glm::vec2 lo(2.f), hi = glm::max(glm::vec2(2.f), glm::vec2(width, height) - size - 2.f);
    const glm::vec2 wanted = glm::clamp(glm::round(anchored), lo, hi);
    auto overlaps = [&](glm::vec2 o) {
      for (const glm::vec4& r : placed)
        if (o.x < r.z && o.x + size.x > r.x && o.y < r.w && o.y + size.y > r.y) return true;
      for (const glm::vec2& m : markers)
        if (o.x < m.x + markerClearPx && o.x + size.x > m.x - markerClearPx && o.y < m.y + markerClearPx &&
            o.y + size.y > m.y - markerClearPx)
          return true;
      return false;
    };
    // Greedy: the wanted place, else near it (up or down by up to two lines, then the same on the
    // other side of its marker), so a label never strays far from its point; when all overlap,
    // the wanted place after all.
    std::vector<glm::vec2> candidates{wanted};
    const float steps[] = {0.6f, -0.6f, 1.1f, -1.1f, 1.7f, -1.7f, 2.3f, -2.3f};
    for (float step : steps) candidates.push_back(wanted + glm::vec2(0, step * size.y));
    if (l.marker) {
      const glm::vec2 mirrored(2 * float(l.marker->x) - wanted.x - size.x, wanted.y);  // the same gap, left
      candidates.push_back(mirrored);
      for (float step : steps) candidates.push_back(mirrored + glm::vec2(0, step * size.y));
    }
    glm::vec2 origin = wanted;
    if (l.avoid)
      for (const glm::vec2& c : candidates) {
        const glm::vec2 clamped = glm::round(glm::clamp(c, lo, hi));
        if (!overlaps(clamped)) {
          origin = clamped;
          break;
        }
      }
    placed.emplace_back(origin.x, origin.y, origin.x + size.x, origin.y + size.y);
    out.push_back(origin);
  }
  return out;
}

const ImFont* TextRenderer::font(TextSize size) const { return size == TextSize::title ? title_ : label_; }

Vec2 TextRenderer::measure(const std::string& text, TextSize size) const {
  const ImFont* f = font(size);
  const ImVec2 s = const_cast<ImFont*>(f)->CalcTextSizeA(f->FontSize, 1e6f, 0.f, text.c_str());
  return {s.x, s.y};
}

glm::vec2 TextRenderer::topLeft(const TextLabel& label) const {
  const Vec2 size = measure(label.text, label.size);
  glm::vec2 origin(label.pixel);
  switch (label.anchor) {
    case Anchor::topLeft: break;
    case Anchor::center: origin -= glm::vec2(size) * 0.5f; break;
    case Anchor::left: origin.y -= float(size.y) * 0.5f; break;
    case Anchor::bottomLeft: origin.y -= float(size.y); break;
    case Anchor::topCenter: origin.x -= float(size.x) * 0.5f; break;
  }
  return glm::round(origin);
}

void TextRenderer::appendText(const TextLabel& label, const glm::vec2& origin, const glm::vec4& color,
                              std::vector<float>& out) const {
  const ImFont* f = font(label.size);
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

void TextRenderer::draw(const std::vector<TextLabel>& labels, int width, int height) {
  if (labels.empty()) return;
  std::vector<float> vertices;
  const std::vector<glm::vec2> origins =
      placeLabels(labels, [this](const TextLabel& l) { return measure(l.text, l.size); }, width, height, 7.f * scale_);
  placed_.clear();
  for (size_t i = 0; i < labels.size(); ++i) {
    const TextLabel& l = labels[i];
    const glm::vec2 origin = origins[i];
    const glm::vec2 size(measure(l.text, l.size));
    placed_.emplace_back(origin.x, origin.y, origin.x + size.x, origin.y + size.y);
    if (l.shadow) {
      const glm::vec4 dark(0.f, 0.f, 0.f, 0.75f * l.color.a);
      for (const glm::vec2 o : {glm::vec2(-1, 0), glm::vec2(1, 0), glm::vec2(0, -1), glm::vec2(0, 1)})
        appendText(l, origin + o, dark, vertices);
    }
    appendText(l, origin, l.color, vertices);
  }
  const GladGLContext& gl = *gl_;
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
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
