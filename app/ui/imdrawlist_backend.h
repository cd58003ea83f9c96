// A third backend for display lists (app/views/display_list.h), beside the GL and SVG ones: draws a
// list's 2D batches into a Dear ImGui ImDrawList, so that a chart built once in app/views (the depth
// plot) appears inside a panel with the panel's own font, clipping and tooltips.
//
// It draws only what needs no depth buffer and no 3D camera: Lines, Points and Triangles in
// Space::pixels with Depth::ignore, and Text. A Fill, a batch in another space or a depth-tested
// batch is refused with std::invalid_argument (draw such a list with the GL backend into a texture).
#pragma once

#include "app/views/display_list.h"
#include "app/views/labels.h"

#include <imgui.h>

namespace vplab::ui {

/// Text measured with Dear ImGui's current font (ImGui::GetFont()): labels at its size, titles 4/3
/// of it (as the views' 15 and 20 px fonts), widths rounded up as ImGui::CalcTextSize rounds them.
/// `scale` is the lecture mode's UI scale (line widths and markers grow with it). Needs a current
/// ImGui frame.
class ImGuiTextMetrics final : public TextMetrics {
 public:
  explicit ImGuiTextMetrics(float scale) : scale_(scale) {}
  Vec2 measure(std::string_view text, TextSize size) const override;
  float scale() const override { return scale_; }
  /// The font size a TextSize is drawn at.
  static float fontSize(TextSize size);

 private:
  float scale_;
};

struct ImDrawListOptions {
  bool background = false;  // fill the list's rectangle with its background (else the window's shows)
};

/// Draws `list` with its top-left pixel at `origin` (screen coordinates), clipped to its
/// width × height. Text is drawn with ImGui's current font at ImGuiTextMetrics' sizes: place the
/// labels with an ImGuiTextMetrics. Lines take their first vertex's colour (ImDrawList draws a line
/// in one colour); triangles keep each vertex's.
void drawDisplayList(ImDrawList& out, const draw::DisplayList& list, ImVec2 origin, const ImDrawListOptions& options = {});

}  // namespace vplab::ui
