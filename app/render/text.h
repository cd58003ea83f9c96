// Labels and titles in a view's pixel space (origin top-left, y down), drawn with glyphs from a font
// atlas baked by Dear ImGui's ImFontAtlas (DejaVu Sans when installed, else ImGui's built-in font),
// so text looks the same in every backend, headless or not.
#pragma once

#include "app/gl/objects.h"
#include "app/gl/shader.h"
#include "pipeline/math.h"

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct ImFontAtlas;
struct ImFont;

namespace vplab {

enum class TextSize { label, title };
enum class Anchor { topLeft, center, left, bottomLeft, topCenter };

struct TextLabel {
  Vec2 pixel;
  std::string text;  // UTF-8
  glm::vec4 color{1, 1, 1, 1};
  TextSize size = TextSize::label;
  Anchor anchor = Anchor::left;
  bool shadow = true;  // a dark outline keeps labels readable on any background
  bool avoid = true;   // moved near its place when it would overlap a label placed before it or a marker
  /// The point the label names (a drawn marker, pixels): no label may cover it.
  std::optional<Vec2> marker{};
};

/// Where each label goes (its top-left corner, pixels): anchored, rounded, clamped to the width ×
/// height view, and moved near its place when it would overlap a label placed before it or come
/// within `markerClearPx` of any label's marker. TextRenderer::draw and the SVG export share it.
std::vector<glm::vec2> placeLabels(const std::vector<TextLabel>& labels,
                                   const std::function<Vec2(const TextLabel&)>& measure, int width, int height,
                                   float markerClearPx);

class TextRenderer {
 public:
  /// `scale` enlarges all text (lecture mode on a projector).
  TextRenderer(const GladGLContext& gl, float scale = 1.f);
  ~TextRenderer();
  /// Draws the labels into the current viewport of width × height pixels.
  void draw(const std::vector<TextLabel>& labels, int width, int height);
  /// Width and height in pixels of a text at a size.
  Vec2 measure(const std::string& text, TextSize size) const;
  float scale() const { return scale_; }
  /// Where the last draw put each label: x0, y0, x1, y1 in pixels (for the tests).
  const std::vector<glm::vec4>& placed() const { return placed_; }

 private:
  glm::vec2 topLeft(const TextLabel& label) const;
  void appendText(const TextLabel& label, const glm::vec2& origin, const glm::vec4& color,
                  std::vector<float>& out) const;
  const ImFont* font(TextSize size) const;

  const GladGLContext* gl_;
  float scale_ = 1.f;
  std::vector<glm::vec4> placed_;
  std::unique_ptr<ImFontAtlas> atlas_;
  ImFont* label_ = nullptr;
  ImFont* title_ = nullptr;
  gl::Program program_;
  gl::Texture texture_;
  gl::VertexArray vao_;
  gl::Buffer vbo_;
};

}  // namespace vplab
