// Small ImGui helpers shared by the panels: double-precision drags, bilingual tooltips, and the
// record of where named widgets were drawn (for the UI tests).
#pragma once

#include "app/ui/viewer_state.h"

#include <imgui.h>

namespace vplab::ui {

/// A drag field for a WC vector; records its rect as `id` in s.rects.
bool dragVec3(ViewerState& s, const char* label, const char* id, Vec3& v, float speed = 0.02f);
bool dragDouble(ViewerState& s, const char* label, const char* id, double& v, float speed = 0.01f,
                double min = 0, double max = 0, const char* format = "%.3f");
/// Remembers the last item's screen rect under `id`.
void recordRect(ViewerState& s, const char* id);
/// A tooltip on the last item: the English explanation, then the German one of the lecture notes.
void tooltip(const char* english, const char* german);
/// A (?) marker with a tooltip.
void help(const char* english, const char* german);
void errorText(const std::string& text);
/// A separator with a small heading.
void section(const char* title);
/// "(0.1235, -2, 3.5)".
std::string vecText(const Vec3& v);
std::string vecText(const Vec4& v);

}  // namespace vplab::ui
