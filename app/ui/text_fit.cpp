#include "app/ui/text_fit.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

namespace vplab::ui {

std::vector<std::string> textCutOff() {
  std::vector<std::string> problems;
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data) return problems;  // no frame drawn yet
  const ImGuiIO& io = ImGui::GetIO();
  // A glyph's vertex has one of its glyph's texture corners (other shapes use the white pixel or
  // the baked lines).
  std::map<std::pair<float, float>, const ImFontGlyph*> corners;  // → the glyph, to name it
  for (const ImFontGlyph& g : ImGui::GetFont()->Glyphs)
    for (float u : {g.U0, g.U1})
      for (float v : {g.V0, g.V1}) corners.emplace(std::pair{u, v}, &g);
  // A glyph whose ink reaches before its pen position (the hook of "j", the bar of "T": a negative
  // left bearing) or past its advance does so by design: a line that starts at the clip rectangle's
  // edge loses only that overhang, by which the rule lets it reach across (in font pixels × scale).
  const float scale = ImGui::GetFontSize() / ImGui::GetFont()->FontSize;
  const ImFontGlyph* ellipsis = ImGui::GetFont()->FindGlyphNoFallback(0x2026);
  for (int l = 0; l < data->CmdListsCount; ++l) {
    const ImDrawList* list = data->CmdLists[l];
    const std::string owner = list->_OwnerName ? list->_OwnerName : "?";
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != io.Fonts->TexID) continue;
      for (unsigned i = 0; i < cmd.ElemCount; ++i) {
        const ImDrawVert& v = list->VtxBuffer[list->IdxBuffer[cmd.IdxOffset + i] + cmd.VtxOffset];
        const auto glyph = corners.find({v.uv.x, v.uv.y});
        if (glyph == corners.end()) continue;  // a shape, not a glyph
        char where[96];
        const ImFontGlyph& g = *glyph->second;
        std::snprintf(where, sizeof where, " at (%.0f, %.0f), glyph U+%04X", v.pos.x, v.pos.y, unsigned(g.Codepoint));
        const float before = v.uv.x == g.U0 ? std::max(0.f, -g.X0) * scale : 0.f;
        const float after = v.uv.x == g.U1 ? std::max(0.f, g.X1 - g.AdvanceX) * scale : 0.f;
        if (v.pos.x < cmd.ClipRect.x - 0.5f - before || v.pos.x > cmd.ClipRect.z + 0.5f + after) {
          problems.push_back(owner + ": text cut off" + where);
          break;  // one per command is enough
        }
        if (ellipsis && v.uv.x == ellipsis->U0 && v.uv.y == ellipsis->V0) {
          problems.push_back(owner + ": text shortened to \"…\"" + where);
          break;
        }
      }
    }
  }
  return problems;
}

}  // namespace vplab::ui
