// A finger is not a mouse pointer (issue 41): where the last pointer was a finger (the page on a
// phone or a tablet, ViewerModel::touch), every target is a finger's size and a handle is hit within
// a finger's radius. The sizes are the platforms' guidelines: Apple's 44 pt, Material's 48 dp (a
// touch target of 44 CSS px or more), and a finger's contact patch of about 10 mm (a radius of
// 20 CSS px). A CSS pixel is ViewerModel::cssPixel screen pixels (the page's devicePixelRatio; its UI
// scale may be a little smaller on a phone, to hold a line of fields).
#pragma once

#include <algorithm>

namespace vplab::ui {

/// A tap target's least height (and a field's, a tab's, a menu entry's), in CSS px before the UI scale.
inline constexpr float kTouchTargetPx = 44;
/// The gap between two targets on touch, in CSS px before the UI scale.
inline constexpr float kTouchGapPx = 8;
/// How far from a handle's or a vertex's centre a finger still hits it, in CSS px before the UI scale
/// (the nearest wins, pickHandle and pickVertex).
inline constexpr float kTouchRadiusPx = 20;

/// Screen pixels a length of `cssPx` CSS pixels takes for a finger: never less than the UI scale
/// makes it (a lecturer's larger scale keeps its larger targets).
inline float fingerPixels(float cssPx, float uiScale, float cssPixel) { return cssPx * std::max(uiScale, cssPixel); }

}  // namespace vplab::ui
