#include "app/ui/text_fit.h"

#include <imgui.h>

#include <cstdio>
#include <set>
#include <utility>

namespace vplab::ui {

std::vector<std::string> textCutOff() {
  std::vector<std::string> problems;
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data) return problems;  // no frame drawn yet
  const ImGuiIO& io = ImGui::GetIO();
  // A glyph's vertex has one of its glyph's texture corners (other shapes use the white pixel or
  // the baked lines).
  std::set<std::pair<float, float>> corners;
  for (const ImFontGlyph& g : ImGui::GetFont()->Glyphs)
    for (float u : {g.U0, g.U1})
      for (float v : {g.V0, g.V1}) corners.insert({u, v});
  const ImFontGlyph* ellipsis = ImGui::GetFont()->FindGlyphNoFallback(0x2026);
  for (int l = 0; l < data->CmdListsCount; ++l) {
    const ImDrawList* list = data->CmdLists[l];
    const std::string owner = list->_OwnerName ? list->_OwnerName : "?";
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != io.Fonts->TexID) continue;
      for (unsigned i = 0; i < cmd.ElemCount; ++i) {
        const ImDrawVert& v = list->VtxBuffer[list->IdxBuffer[cmd.IdxOffset + i] + cmd.VtxOffset];
        if (!corners.count({v.uv.x, v.uv.y})) continue;  // a shape, not a glyph
        char where[96];
        std::snprintf(where, sizeof where, " at (%.0f, %.0f)", v.pos.x, v.pos.y);
        if (v.pos.x < cmd.ClipRect.x - 0.5f || v.pos.x > cmd.ClipRect.z + 0.5f) {
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
