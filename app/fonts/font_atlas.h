// The labels' fonts, measured and rasterised by Dear ImGui's ImFontAtlas (stb_truetype; no GL):
// DejaVu Sans at 15 px (labels) and 20 px (titles) times the lecture mode's scale when it is
// installed, else Dear ImGui's built-in font. The views place text with these metrics
// (app/views/labels.h), the GL backend draws these glyphs, the SVG names the same font and size.
#pragma once

#include "app/views/labels.h"

#include <cstdint>
#include <memory>

struct ImFontAtlas;
struct ImFont;

namespace vplab {

class FontAtlas final : public TextMetrics {
 public:
  /// Throws vplab::Error when the atlas cannot be built.
  explicit FontAtlas(float scale = 1.f);
  ~FontAtlas() override;
  FontAtlas(const FontAtlas&) = delete;
  FontAtlas& operator=(const FontAtlas&) = delete;

  Vec2 measure(std::string_view text, TextSize size) const override;
  float scale() const override { return scale_; }

  const ImFont* font(TextSize size) const { return size == TextSize::title ? title_ : label_; }
  /// The glyphs' coverage, one byte per texel, for a texture (the GL backend).
  struct Alpha8 {
    const uint8_t* pixels = nullptr;
    int width = 0, height = 0;
  };
  Alpha8 alpha8() const;

  /// For SVG: the font's CSS family (DejaVu Sans, else ImGui's built-in bitmap font), its em in
  /// pixels (Dear ImGui sizes a font by its line height, SVG by its em) and the baseline below the
  /// top of a line (Dear ImGui puts glyphs at round(ascent)).
  const char* cssFamily() const { return dejaVu_ ? "DejaVu Sans, Verdana, sans-serif" : "monospace"; }
  double emPx(TextSize size) const;
  double baselinePx(TextSize size) const;

 private:
  float scale_ = 1.f;
  bool dejaVu_ = false;
  std::unique_ptr<ImFontAtlas> atlas_;
  ImFont* label_ = nullptr;
  ImFont* title_ = nullptr;
};

}  // namespace vplab
