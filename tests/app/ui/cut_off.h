// The cut-off rule checked over whole panels (issue 37 item 3, issue 40): ImGui draws only what is in
// view, so each scrolled window is paged from top to bottom and ui::textCutOff() read on every page.
#pragma once

#include "app/ui/headless_viewer.h"
#include "app/ui/text_fit.h"
#include "tests/support/gl_test_support.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <string>
#include <utility>
#include <vector>

namespace vplab::test {

/// ui::textCutOff() of every scrolled panel from top to bottom (ImGui draws only what is in view); a
/// page with problems is left in the test output directory as PREFIX-page-N.png.
inline std::vector<std::string> clippedTextOfEveryPage(HeadlessViewer& v, const std::string& prefix) {
  std::vector<std::string> problems = ui::textCutOff();
  for (int page = 0; page < 30; ++page) {
    std::vector<std::pair<ImGuiWindow*, float>> before;
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
      if (w->Active && w->ScrollMax.y > 0 && w->Scroll.y < w->ScrollMax.y - 0.5f) {
        before.emplace_back(w, w->Scroll.y);
        ImGui::SetScrollY(w, w->Scroll.y + w->InnerRect.GetHeight() * 0.8f);
      }
    if (before.empty()) break;
    v.frames(2);
    bool moved = false;
    for (const auto& [w, y] : before) moved |= w->Scroll.y != y;
    if (!moved) break;
    const std::vector<std::string> more = ui::textCutOff();
    if (!more.empty()) writePng(v.image(), outputDir() / (prefix + "-page-" + std::to_string(page + 1) + ".png"));
    for (const std::string& p : more) problems.push_back(p);
  }
  return problems;
}

}  // namespace vplab::test
