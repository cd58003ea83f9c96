// The one font of vplab's text, the views' labels and the viewer's panels alike, and the glyphs
// taken from it (docs/lecturers.md "The viewer"; the page preloads the same file, app/web/CMakeLists.txt).
#pragma once

#include <cstdint>

namespace vplab {

/// DejaVu Sans from Debian's fonts-dejavu-core; without it Dear ImGui's built-in bitmap font is used.
inline constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Dear ImGui's glyph ranges (pairs of code points, 0-terminated, ImWchar16): Latin, Greek (φ, α),
/// punctuation, super- and subscripts, arrows (→) and mathematical operators (≤, ⋅; ÷ is Latin-1).
inline constexpr std::uint16_t kFontGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2070,
                                                     0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

}  // namespace vplab
