// The text a frame of the viewer put on the screen, read back from Dear ImGui's draw data (for the
// tests): every glyph is a textured quad whose texture coordinates name it in the font atlas, and
// whose draw command's clip rectangle says whether it can be seen. So this is what a user reads in
// the window (not scrolled away, not outside its panel, not cut at a border), with where it is: the
// oracle for "the value the caption cites is on screen" (issue 37). Glyphs cut by a border are not
// read (ImGui clips them on the CPU and their texture coordinates change), nor is text inside the
// views' images (their labels are in the display lists: app/views/labels.h).
#pragma once

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vplab::test {

struct ScreenLine {
  std::string text;  // UTF-8, a space where the pen jumped at least half a space
  ImVec2 min, max;   // the glyphs' box, screen pixels
};

namespace detail {

inline void appendUtf8(std::string& out, unsigned c) {
  if (c < 0x80) {
    out += char(c);
  } else if (c < 0x800) {
    out += char(0xC0 | (c >> 6));
    out += char(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += char(0xE0 | (c >> 12));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  } else {
    out += char(0xF0 | (c >> 18));
    out += char(0x80 | ((c >> 12) & 0x3F));
    out += char(0x80 | ((c >> 6) & 0x3F));
    out += char(0x80 | (c & 0x3F));
  }
}

struct Glyph {
  const ImFontGlyph* glyph;
  const ImFont* font;
};

struct Placed {
  const ImFontGlyph* glyph;
  const ImFont* font;
  float scale;       // drawn size / the atlas's
  ImVec2 min, max;   // the quad
  float lineTop;     // the pen's line: the quad's top less the glyph's offset
  float penX;        // where the pen stood
};

}  // namespace detail

/// The lines of text the last rendered frame shows, top to bottom, left to right.
inline std::vector<ScreenLine> screenText() {
  using detail::Placed;
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data || !data->Valid) return {};
  // The atlas's glyphs by their texture coordinates' top-left corner.
  std::map<std::pair<float, float>, detail::Glyph> byUv;
  const ImFontAtlas* atlas = ImGui::GetIO().Fonts;
  for (const ImFont* font : atlas->Fonts)
    for (const ImFontGlyph& g : font->Glyphs)
      if (g.Visible) byUv.emplace(std::make_pair(g.U0, g.V0), detail::Glyph{&g, font});
  std::vector<Placed> glyphs;
  for (int l = 0; l < data->CmdListsCount; ++l) {
    const ImDrawList* list = data->CmdLists[l];
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) continue;
      const ImDrawIdx* idx = list->IdxBuffer.Data + cmd.IdxOffset;
      const ImDrawVert* vtx = list->VtxBuffer.Data + cmd.VtxOffset;
      for (unsigned i = 0; i + 6 <= cmd.ElemCount;) {
        // A glyph is PrimRectUV's quad: a, b, c, then a, c, d.
        const ImDrawIdx a = idx[i];
        const bool quad = idx[i + 1] == a + 1 && idx[i + 2] == a + 2 && idx[i + 3] == a && idx[i + 4] == a + 2 &&
                          idx[i + 5] == a + 3;
        if (!quad) {
          i += 3;
          continue;
        }
        const ImDrawVert &va = vtx[a], &vc = vtx[a + 2];
        const auto it = byUv.find({va.uv.x, va.uv.y});
        if (it == byUv.end() || it->second.glyph->U1 != vc.uv.x || it->second.glyph->V1 != vc.uv.y) {
          i += 6;
          continue;
        }
        i += 6;
        // Seen only inside its command's clip rectangle (the GPU's scissor).
        if (va.pos.x < cmd.ClipRect.x - 0.5f || va.pos.y < cmd.ClipRect.y - 0.5f || vc.pos.x > cmd.ClipRect.z + 0.5f ||
            vc.pos.y > cmd.ClipRect.w + 0.5f)
          continue;
        const ImFontGlyph* g = it->second.glyph;
        const float scale = (vc.pos.x - va.pos.x) / std::max(1e-6f, g->X1 - g->X0);
        glyphs.push_back({g, it->second.font, scale, va.pos, vc.pos, va.pos.y - g->Y0 * scale, va.pos.x - g->X0 * scale});
      }
    }
  }
  // Lines: glyphs whose pen lines agree within a pixel, left to right.
  std::sort(glyphs.begin(), glyphs.end(), [](const Placed& p, const Placed& q) {
    if (std::abs(p.lineTop - q.lineTop) > 1.f) return p.lineTop < q.lineTop;
    return p.penX < q.penX;
  });
  std::vector<ScreenLine> lines;
  const Placed* last = nullptr;
  for (const Placed& p : glyphs) {
    const ImFontGlyph* blank = p.font->FindGlyphNoFallback(' ');
    const float space = 0.4f * p.scale * (blank ? blank->AdvanceX : p.font->FontSize * 0.25f);
    const bool sameLine = last && std::abs(p.lineTop - last->lineTop) <= 1.f;
    const float lastEnd = last ? last->penX + last->glyph->AdvanceX * last->scale : 0.f;
    if (!sameLine || p.penX - lastEnd > 12.f * space) {  // a new line, or a column far apart
      lines.push_back({{}, p.min, p.max});
    } else if (p.penX - lastEnd > space) {
      lines.back().text += ' ';
    }
    ScreenLine& line = lines.back();
    detail::appendUtf8(line.text, p.glyph->Codepoint);
    line.min = ImVec2(std::min(line.min.x, p.min.x), std::min(line.min.y, p.min.y));
    line.max = ImVec2(std::max(line.max.x, p.max.x), std::max(line.max.y, p.max.y));
    last = &p;
  }
  return lines;
}

/// All the screen's text, a line a row (for a failure's message).
inline std::string screenTextDump(const std::vector<ScreenLine>& lines) {
  std::string out;
  for (const ScreenLine& l : lines) out += l.text + "\n";
  return out;
}

/// Whether some line on the screen holds `s`.
inline bool onScreen(const std::vector<ScreenLine>& lines, const std::string& s) {
  return std::any_of(lines.begin(), lines.end(), [&](const ScreenLine& l) { return l.text.find(s) != std::string::npos; });
}

}  // namespace vplab::test
