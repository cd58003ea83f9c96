#include "app/fonts/font_atlas.h"

#include "app/fonts/font_file.h"

#include "base/error.h"

#include <imgui.h>

#include <cmath>
#include <filesystem>

namespace vplab {

namespace {

static_assert(sizeof(ImWchar) == sizeof(kFontGlyphRanges[0]), "Dear ImGui built with 16-bit ImWchar");
const ImWchar* const kGlyphRanges = reinterpret_cast<const ImWchar*>(kFontGlyphRanges);
// DejaVu Sans: 2048 units per em, hhea ascent 1901, descent −483; Dear ImGui's size is their sum.
constexpr double kDejaVuEmPerLine = 2048.0 / (1901.0 + 483.0);

}  // namespace

FontAtlas::FontAtlas(float scale) : scale_(scale), atlas_(std::make_unique<ImFontAtlas>()) {
  if (std::filesystem::exists(kFontFile)) {
    label_ = atlas_->AddFontFromFileTTF(kFontFile, 15.f * scale, nullptr, kGlyphRanges);
    title_ = atlas_->AddFontFromFileTTF(kFontFile, 20.f * scale, nullptr, kGlyphRanges);
    dejaVu_ = label_ && title_;
  }
  if (!label_ || !title_) {
    ImFontConfig config;
    config.SizePixels = 13.f * std::max(1.f, std::round(scale));
    label_ = title_ = atlas_->AddFontDefault(&config);
  }
  if (!atlas_->Build()) throw Error("cannot build the labels' font atlas");
}

FontAtlas::~FontAtlas() = default;

Vec2 FontAtlas::measure(std::string_view text, TextSize size) const {
  ImFont* f = const_cast<ImFont*>(font(size));
  const ImVec2 s = f->CalcTextSizeA(f->FontSize, 1e6f, 0.f, text.data(), text.data() + text.size());
  return {s.x, s.y};
}

FontAtlas::Alpha8 FontAtlas::alpha8() const {
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  atlas_->GetTexDataAsAlpha8(&pixels, &w, &h);
  return {pixels, w, h};
}

double FontAtlas::emPx(TextSize size) const { return font(size)->FontSize * (dejaVu_ ? kDejaVuEmPerLine : 1.0); }

double FontAtlas::baselinePx(TextSize size) const { return std::round(font(size)->Ascent); }

}  // namespace vplab
