// Draws placed labels (app/views/labels.h) in a view's pixels (origin top-left, y down) with the
// glyphs of a FontAtlas (Dear ImGui's, baked on the CPU), so text looks the same in every context,
// headless or not.
#pragma once

#include "app/fonts/font_atlas.h"
#include "app/gl/objects.h"
#include "app/gl/shader.h"
#include "app/views/labels.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace vplab {

class TextRenderer {
 public:
  /// `scale` enlarges all text (lecture mode on a projector).
  TextRenderer(const GladGLContext& gl, float scale = 1.f);
  ~TextRenderer();
  /// Draws labels placed by the views (labels.h) into the current viewport of width × height pixels.
  void draw(const std::vector<PlacedLabel>& labels, const glm::vec3& outline, int width, int height);
  /// Width and height in pixels of a text at a size.
  Vec2 measure(const std::string& text, TextSize size) const { return atlas_->measure(text, size); }
  float scale() const { return atlas_->scale(); }
  const FontAtlas& atlas() const { return *atlas_; }
  /// Where the last draw put each label: x0, y0, x1, y1 in pixels (for the tests).
  const std::vector<glm::vec4>& placed() const { return placed_; }

 private:
  void appendText(const PlacedLabel& label, const glm::vec2& origin, const glm::vec4& color,
                  std::vector<float>& out) const;

  const GladGLContext* gl_;
  std::unique_ptr<FontAtlas> atlas_;
  std::vector<glm::vec4> placed_;
  gl::Program program_;
  gl::Texture texture_;
  gl::VertexArray vao_;
  gl::Buffer vbo_;
};

}  // namespace vplab
