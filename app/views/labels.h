// Labels and titles in a view's pixels (origin top-left, y down), placed once for every backend in
// one layout pass over the view: anchored, rounded, kept inside the view, off each other, off the
// points they name and off the view's axes; a label that finds no place near its point is
// shortened, or dropped when a more important one needs the room (issue 37: labels never sit on
// each other, and each stays by what it names).
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
  /// Placed before the less important, which give way (moved, shortened, dropped) when both want a place.
  int priority = 0;
  /// Shown instead when the text finds no place near its point ("vordere Ebene F" → "F").
  std::string shortText{};
};

/// A line drawn in the view (an axis) that no label may cross, in pixels.
struct LabelObstacle {
  Vec2 a, b;
};

/// A label where it goes: its top-left corner and size in pixels.
struct PlacedLabel {
  glm::vec2 topLeft;
  glm::vec2 extent;  // width, height
  std::string text;
  glm::vec4 color;
  TextSize size = TextSize::label;
  bool shadow = true;
  /// The point it names (its marker, else the place asked for) and how far from it the label may
  /// be: its nearest edge within `reach` pixels (what the tests check).
  glm::vec2 anchor{0, 0};
  float reach = 0;
};

/// How large a text is, and the lecture mode's scale (text, line widths and markers grow with it).
class TextMetrics {
 public:
  virtual ~TextMetrics() = default;
  /// Width and height in pixels of a one-line text at a size.
  virtual Vec2 measure(std::string_view text, TextSize size) const = 0;
  virtual float scale() const = 0;
};

/// Places the labels in a width × height view, the more important first (by priority, then in
/// order): anchored and rounded. A label that would leave the view, overlap a label placed before
/// it, come within 7 px (× scale) of a marker or cross an obstacle is moved around its point (never
/// farther than 2.5 lines and a gap), then tried in its short text, then dropped. Labels that do not
/// avoid (titles, a plot's fixed scale) stay where asked and are placed first. A label that says
/// what one placed before it says about the same point is dropped (a highlighted handle's name
/// beside the overlay's).
std::vector<PlacedLabel> placeLabels(const std::vector<TextLabel>& labels, const TextMetrics& metrics, int width,
                                     int height, const std::vector<LabelObstacle>& obstacles = {});

/// How far a placed label's box is from a point (0 inside it), in pixels.
float distanceToBox(const PlacedLabel& label, glm::vec2 point);

}  // namespace vplab
