#include "app/ui/text_fit.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace vplab::ui {

namespace {

using Corners = std::map<std::pair<float, float>, const ImFontGlyph*>;

/// Whether the ellipsis whose top left vertex is the command's index `at` is a character of running
/// text ("… 0.0025" in a caption: the next glyph follows within a space and a half on its line)
/// rather than ImGui's mark of a shortened label, which ends the label (what follows it is at least
/// a frame's padding away).
bool inRunningText(const ImDrawList& list, const ImDrawCmd& cmd, unsigned at, const Corners& corners, float scale) {
  const ImDrawVert& e = list.VtxBuffer[list.IdxBuffer[cmd.IdxOffset + at] + cmd.VtxOffset];
  const ImFont* font = ImGui::GetFont();
  const ImFontGlyph* ellipsis = font->FindGlyphNoFallback(0x2026);
  const ImFontGlyph* space = font->FindGlyphNoFallback(' ');
  if (!ellipsis || !space) return false;
  const float end = e.pos.x - ellipsis->X0 * scale + ellipsis->AdvanceX * scale;  // the pen after "…"
  for (unsigned i = at + 1; i < cmd.ElemCount && i < at + 12; ++i) {
    const ImDrawVert& v = list.VtxBuffer[list.IdxBuffer[cmd.IdxOffset + i] + cmd.VtxOffset];
    const auto g = corners.find({v.uv.x, v.uv.y});
    if (g == corners.end() || g->second == ellipsis || v.uv.x != g->second->U0 || v.uv.y != g->second->V0) continue;
    const float pen = v.pos.x - g->second->X0 * scale;  // the next glyph's pen position
    return std::abs((v.pos.y - g->second->Y0 * scale) - (e.pos.y - ellipsis->Y0 * scale)) < 0.5f &&
           pen >= end - 0.5f && pen <= end + 1.5f * space->AdvanceX * scale;
  }
  return false;
}

}  // namespace

std::vector<std::string> textCutOff() {
  std::vector<std::string> problems;
  const ImDrawData* data = ImGui::GetDrawData();
  if (!data) return problems;  // no frame drawn yet
  const ImGuiIO& io = ImGui::GetIO();
  // A glyph's vertex has one of its glyph's texture corners (other shapes use the white pixel or
  // the baked lines).
  Corners corners;  // → the glyph, to name it
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
        if (ellipsis && v.uv.x == ellipsis->U0 && v.uv.y == ellipsis->V0 && !inRunningText(*list, cmd, i, corners, scale)) {
          problems.push_back(owner + ": text shortened to \"…\"" + where);
          break;
        }
      }
    }
  }
  return problems;
}

}  // namespace vplab::ui
