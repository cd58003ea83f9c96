// Labels and titles in a view's pixels (origin top-left, y down), placed once for every backend:
// anchored, rounded, kept inside the view and moved off each other and off the points they name.
// Text is measured through TextMetrics (app/fonts/font_atlas.h measures with Dear ImGui's font
// atlas, the GL backend draws those very glyphs, the SVG names the same font at the same size).
#pragma once

#include "pipeline/math.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

enum class TextSize { label, title };
enum class Anchor { topLeft, center, left, bottomLeft, topCenter };

/// A label as a view asks for it.
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

/// A label where it goes: its top-left corner and size in pixels.
struct PlacedLabel {
  glm::vec2 topLeft;
  glm::vec2 extent;  // width, height
  std::string text;
  glm::vec4 color;
  TextSize size = TextSize::label;
  bool shadow = true;
};

/// How large a text is, and the lecture mode's scale (text, line widths and markers grow with it).
class TextMetrics {
 public:
  virtual ~TextMetrics() = default;
  /// Width and height in pixels of a one-line text at a size.
  virtual Vec2 measure(std::string_view text, TextSize size) const = 0;
  virtual float scale() const = 0;
};

/// Places the labels in order in a width × height view: anchored, rounded, clamped to the view,
/// and moved near their place when one would overlap a label placed before it or come within
/// 7 px (× scale) of any label's marker.
std::vector<PlacedLabel> placeLabels(const std::vector<TextLabel>& labels, const TextMetrics& metrics, int width,
                                     int height);

}  // namespace vplab
